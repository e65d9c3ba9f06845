#include "window_system.hpp"

#include <atomic>

namespace pfx::inject {
namespace {

// The few GLX and EGL values used here, from the Khronos registry (glx.h, egl.h): the library
// builds without X11's headers.
constexpr int kGlxWidth = 0x801D, kGlxHeight = 0x801E;
constexpr int kEglWidth = 0x3057, kEglHeight = 0x3056, kEglDraw = 0x3059;
constexpr int kEglContextClientType = 0x3097, kEglOpenGlEsApi = 0x30A0, kEglOpenVgApi = 0x30A1;

// A GLX or EGL function of the application's, looked up at its first use and kept: the library
// stays loaded while the application presents through it, so a present costs no lookup. While
// the library is not loaded it is looked up again at the next use.
template <typename Function>
class RealFunction {
 public:
  constexpr RealFunction(Library library, const char* name) : library_(library), name_(name) {}
  Function get() {
    Proc found = found_.load(std::memory_order_acquire);
    if (!found) {
      found = real_proc(library_, name_);
      found_.store(found, std::memory_order_release);
    }
    return reinterpret_cast<Function>(found);
  }

 private:
  const Library library_;
  const char* const name_;
  std::atomic<Proc> found_{nullptr};
};

RealFunction<void* (*)()> glx_current_context{Library::GLX, "glXGetCurrentContext"};
RealFunction<unsigned long (*)()> glx_current_drawable{Library::GLX, "glXGetCurrentDrawable"};
RealFunction<void (*)(void*, unsigned long, int, unsigned*)> glx_query_drawable{Library::GLX, "glXQueryDrawable"};
RealFunction<Proc (*)(const unsigned char*)> glx_get_proc_address{Library::GLX, "glXGetProcAddressARB"};
RealFunction<void* (*)()> egl_current_display{Library::EGL, "eglGetCurrentDisplay"};
RealFunction<void* (*)()> egl_current_context{Library::EGL, "eglGetCurrentContext"};
RealFunction<void* (*)(int)> egl_current_surface{Library::EGL, "eglGetCurrentSurface"};
RealFunction<unsigned (*)(void*, void*, int, int*)> egl_query_surface{Library::EGL, "eglQuerySurface"};
RealFunction<unsigned (*)(void*, void*, int, int*)> egl_query_context{Library::EGL, "eglQueryContext"};
RealFunction<Proc (*)(const char*)> egl_get_proc_address{Library::EGL, "eglGetProcAddress"};

}  // namespace

const char* window_system_name(WindowSystem system) { return system == WindowSystem::GLX ? "GLX" : "EGL"; }

void* current_context(WindowSystem system) {
  auto get = system == WindowSystem::GLX ? glx_current_context.get() : egl_current_context.get();
  return get ? get() : nullptr;
}

bool presents_current_surface(const PresentCall& call) {
  if (call.system == WindowSystem::GLX) {
    auto get = glx_current_drawable.get();
    return get && get() == call.surface;
  }
  auto get = egl_current_surface.get();
  return get && reinterpret_cast<unsigned long>(get(kEglDraw)) == call.surface;
}

bool surface_size(const PresentCall& call, int* width, int* height) {
  if (call.system == WindowSystem::GLX) {
    auto query = glx_query_drawable.get();
    if (!query) return false;
    unsigned w = 0, h = 0;
    query(call.display, call.surface, kGlxWidth, &w);
    query(call.display, call.surface, kGlxHeight, &h);
    *width = static_cast<int>(w);
    *height = static_cast<int>(h);
    return w > 0 && h > 0;
  }
  auto query = egl_query_surface.get();
  if (!query) return false;
  void* surface = reinterpret_cast<void*>(call.surface);
  return query(call.display, surface, kEglWidth, width) && query(call.display, surface, kEglHeight, height) &&
         *width > 0 && *height > 0;
}

std::string other_client_api(WindowSystem system) {
  if (system == WindowSystem::GLX) return "";
  auto query = egl_query_context.get();
  auto display = egl_current_display.get();
  int api = 0;
  if (!query || !display || !query(display(), current_context(system), kEglContextClientType, &api)) return "";
  if (api == kEglOpenGlEsApi) return "OpenGL ES";
  if (api == kEglOpenVgApi) return "OpenVG";
  return "";
}

Proc gl_proc(WindowSystem system, const char* name) {
  if (system == WindowSystem::GLX) {
    auto lookup = glx_get_proc_address.get();
    return lookup ? lookup(reinterpret_cast<const unsigned char*>(name)) : nullptr;
  }
  auto lookup = egl_get_proc_address.get();
  return lookup ? lookup(name) : nullptr;
}

}  // namespace pfx::inject
