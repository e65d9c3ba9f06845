// The window-system functions as the application would reach them without us. libpfxinject.so
// defines glXSwapBuffers, eglSwapBuffers, dlsym and their get-proc-address lookups itself (the
// interposers in hooks.cpp); everything it calls of libGL, libEGL and libdl goes through here.
#pragma once

namespace pfx::inject {

using Proc = void (*)();

// The C library's dlsym (ours is an interposer), and its address.
void* real_dlsym(void* handle, const char* name);
void* real_dlsym_function();

// Which library a window-system function lives in.
enum class Library { GLX, EGL };

// The function the application meant by `name`: the one a dlsym or get-proc-address call of the
// application returned before we swapped in ours (remembered with remember()), else the next
// definition after ours in the lookup order, else the one in the library if it is loaded at all
// (never loaded by us). Null when the library is not loaded. For our hooks the function found is
// kept, so only the first present of each kind pays for the lookup.
Proc real_proc(Library library, const char* name);
// Records what the application's lookup (`via`: "dlsym", "glXGetProcAddressARB"...) really
// found, for real_proc.
void remember(const char* name, Proc real, const char* via);
// How the application reached one of our functions: the lookup remembered, or "linked" when it
// called the symbol directly (nothing was remembered).
const char* reached_through(const char* name);

}  // namespace pfx::inject
