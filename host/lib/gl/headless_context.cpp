#include "headless_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstring>

#include "keep_loaded.hpp"

namespace pfx::app {
namespace {

std::string egl_error_text(const char* what) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s failed (EGL error 0x%04x)", what, eglGetError());
  return buffer;
}

GLADapiproc glad_loader(const char* name) {
  return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

}  // namespace

pfx_gl_proc HeadlessContext::get_proc_address(void*, const char* name) {
  return reinterpret_cast<pfx_gl_proc>(eglGetProcAddress(name));
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error, Display display_use) {
  auto fail = [&](const std::string& message) -> std::unique_ptr<HeadlessContext> {
    if (error) *error = "cannot create a headless OpenGL 4.5 core context: " + message;
    return nullptr;
  };
  // What EGL loads from here on (its vendor library, the driver and LLVM) stays loaded after
  // eglTerminate: keep_loaded.hpp says why.
  const std::vector<std::string> loaded_before = loaded_shared_objects();
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client_extensions || !std::strstr(client_extensions, "EGL_MESA_platform_surfaceless"))
    return fail("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless); install libegl-mesa0");
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) return fail("eglGetPlatformDisplayEXT is missing");

  std::unique_ptr<HeadlessContext> self(new HeadlessContext);
  self->terminate_ = display_use == Display::OWN;
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) return fail(egl_error_text("eglGetPlatformDisplayEXT"));
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return fail(egl_error_text("eglInitialize"));
  keep_loaded_since(loaded_before);
  self->display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) return fail(egl_error_text("eglBindAPI(EGL_OPENGL_API)"));

  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) return fail(egl_error_text("eglCreateContext(4.5 core)"));
  self->context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    return fail(egl_error_text("eglMakeCurrent"));
  if (!gladLoadGL(glad_loader)) return fail("could not load the GL 4.5 entry points");

  auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
  };
  self->renderer_ = text(GL_RENDERER) + " | " + text(GL_VERSION);
  return self;
}

HeadlessContext::~HeadlessContext() {
  auto display = static_cast<EGLDisplay>(display_);
  if (display != EGL_NO_DISPLAY && display) {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    if (terminate_) eglTerminate(display);
  }
}

}  // namespace pfx::app
