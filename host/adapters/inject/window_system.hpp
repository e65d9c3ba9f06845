// What the injector asks of GLX or EGL at a present, through the application's own libraries
// (real_symbols.hpp): the current context and drawable, the drawable's size, the GL loader.
#pragma once

#include <string>

#include "real_symbols.hpp"

namespace pfx::inject {

enum class WindowSystem { GLX, EGL };

// One call of glXSwapBuffers or eglSwapBuffers.
struct PresentCall {
  WindowSystem system;
  void* display;
  unsigned long surface;  // the GLXDrawable, or the EGLSurface's address
};

const char* window_system_name(WindowSystem system);
// The calling thread's current context; null when none (or the library is not loaded).
void* current_context(WindowSystem system);
// Whether `call` presents the surface the current context draws to: only then is its back
// buffer the one the current context reads.
bool presents_current_surface(const PresentCall& call);
// The surface's size in pixels; false when it cannot be asked.
bool surface_size(const PresentCall& call, int* width, int* height);
// For EGL: whether the current context is an OpenGL ES one. "" when it is desktop GL, else the
// API's name.
std::string other_client_api(WindowSystem system);
// A GL function of the current context's API, as the application's library gives it.
Proc gl_proc(WindowSystem system, const char* name);

}  // namespace pfx::inject
