#include "window_system.hpp"

namespace pfx::inject {
namespace {

// The few GLX and EGL values used here, from the Khronos registry (glx.h, egl.h): the library
// builds without X11's headers.
constexpr int kGlxWidth = 0x801D, kGlxHeight = 0x801E;
constexpr int kEglWidth = 0x3057, kEglHeight = 0x3056, kEglDraw = 0x3059;
constexpr int kEglContextClientType = 0x3097, kEglOpenGlEsApi = 0x30A0, kEglOpenVgApi = 0x30A1;

template <typename Function>
Function glx(const char* name) {
  return reinterpret_cast<Function>(real_proc(Library::GLX, name));
}
template <typename Function>
Function egl(const char* name) {
  return reinterpret_cast<Function>(real_proc(Library::EGL, name));
}

void* egl_current_display() {
  auto get = egl<void* (*)()>("eglGetCurrentDisplay");
  return get ? get() : nullptr;
}

}  // namespace

const char* window_system_name(WindowSystem system) { return system == WindowSystem::GLX ? "GLX" : "EGL"; }

void* current_context(WindowSystem system) {
  if (system == WindowSystem::GLX) {
    auto get = glx<void* (*)()>("glXGetCurrentContext");
    return get ? get() : nullptr;
  }
  auto get = egl<void* (*)()>("eglGetCurrentContext");
  return get ? get() : nullptr;
}

bool presents_current_surface(const PresentCall& call) {
  if (call.system == WindowSystem::GLX) {
    auto get = glx<unsigned long (*)()>("glXGetCurrentDrawable");
    return get && get() == call.surface;
  }
  auto get = egl<void* (*)(int)>("eglGetCurrentSurface");
  return get && reinterpret_cast<unsigned long>(get(kEglDraw)) == call.surface;
}

bool surface_size(const PresentCall& call, int* width, int* height) {
  if (call.system == WindowSystem::GLX) {
    auto query = glx<void (*)(void*, unsigned long, int, unsigned*)>("glXQueryDrawable");
    if (!query) return false;
    unsigned w = 0, h = 0;
    query(call.display, call.surface, kGlxWidth, &w);
    query(call.display, call.surface, kGlxHeight, &h);
    *width = static_cast<int>(w);
    *height = static_cast<int>(h);
    return w > 0 && h > 0;
  }
  auto query = egl<unsigned (*)(void*, void*, int, int*)>("eglQuerySurface");
  if (!query) return false;
  void* surface = reinterpret_cast<void*>(call.surface);
  return query(call.display, surface, kEglWidth, width) && query(call.display, surface, kEglHeight, height) &&
         *width > 0 && *height > 0;
}

std::string other_client_api(WindowSystem system) {
  if (system == WindowSystem::GLX) return "";
  auto query = egl<unsigned (*)(void*, void*, int, int*)>("eglQueryContext");
  int api = 0;
  if (!query || !query(egl_current_display(), current_context(system), kEglContextClientType, &api)) return "";
  if (api == kEglOpenGlEsApi) return "OpenGL ES";
  if (api == kEglOpenVgApi) return "OpenVG";
  return "";
}

Proc gl_proc(WindowSystem system, const char* name) {
  if (system == WindowSystem::GLX) {
    auto lookup = glx<Proc (*)(const unsigned char*)>("glXGetProcAddressARB");
    return lookup ? lookup(reinterpret_cast<const unsigned char*>(name)) : nullptr;
  }
  auto lookup = egl<Proc (*)(const char*)>("eglGetProcAddress");
  return lookup ? lookup(name) : nullptr;
}

}  // namespace pfx::inject
