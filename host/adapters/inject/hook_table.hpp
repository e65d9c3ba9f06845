// The eight functions libpfxinject.so puts in front of the application's, named once: the
// interposers (hooks.cpp), the real functions remembered behind them (real_symbols.cpp) and the
// lookups that hand ours out all read this list. exports.map, which the linker reads, names the
// same functions and dlsym; a test (inject.exports.map) holds the two together.
#pragma once

#include <cstddef>

#include "real_symbols.hpp"

// X(function, library it belongs to): one line per interposed function.
#define PFX_INJECT_HOOKS(X)           \
  X(glXSwapBuffers, GLX)              \
  X(glXGetProcAddress, GLX)           \
  X(glXGetProcAddressARB, GLX)        \
  X(glXDestroyContext, GLX)           \
  X(eglSwapBuffers, EGL)              \
  X(eglSwapBuffersWithDamageKHR, EGL) \
  X(eglGetProcAddress, EGL)           \
  X(eglDestroyContext, EGL)

namespace pfx::inject {

enum class Hook {
#define PFX_INJECT_HOOK_ENUM(function, library) function,
  PFX_INJECT_HOOKS(PFX_INJECT_HOOK_ENUM)
#undef PFX_INJECT_HOOK_ENUM
};

struct HookName {
  const char* name;
  Library library;
};

constexpr HookName kHooks[] = {
#define PFX_INJECT_HOOK_NAME(function, library) {#function, Library::library},
    PFX_INJECT_HOOKS(PFX_INJECT_HOOK_NAME)
#undef PFX_INJECT_HOOK_NAME
};
constexpr size_t kHookCount = sizeof kHooks / sizeof kHooks[0];

constexpr const HookName& hook_name(Hook hook) { return kHooks[static_cast<size_t>(hook)]; }

// The index in kHooks of `name`, or -1 when it is none of ours. Compares by hand, not with
// strcmp, and is not instrumented: dlsym's entry asks it for every lookup, and a sanitizer's
// runtime looks its own functions up with dlsym while it starts, before instrumented code or its
// strcmp interceptor may run.
__attribute__((no_sanitize_address, no_sanitize_undefined)) inline int hook_index(const char* name) {
  if (!name) return -1;
  for (size_t hook = 0; hook < kHookCount; ++hook) {
    const char* ours = kHooks[hook].name;
    size_t i = 0;
    while (ours[i] && ours[i] == name[i]) ++i;
    if (ours[i] == name[i]) return static_cast<int>(hook);
  }
  return -1;
}

}  // namespace pfx::inject
