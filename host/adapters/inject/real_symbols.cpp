#include "real_symbols.hpp"

#include <dlfcn.h>

#include <array>
#include <atomic>

#include "hook_table.hpp"

namespace pfx::inject {
namespace {

using DlsymFunction = void* (*)(void*, const char*);

// Not instrumented: a sanitizer runtime looks its own functions up with dlsym(RTLD_NEXT, ...)
// while it starts, before instrumented code may run, and that first call lands here.
__attribute__((no_sanitize_address, no_sanitize_undefined)) DlsymFunction find_real_dlsym() {
  // glibc 2.34 moved dlsym into libc under a new version; older binaries bind the old one. Both
  // are the same function; dlvsym is not interposed, so it reaches libc directly.
  if (void* found = dlvsym(RTLD_NEXT, "dlsym", "GLIBC_2.34")) return reinterpret_cast<DlsymFunction>(found);
  return reinterpret_cast<DlsymFunction>(dlvsym(RTLD_NEXT, "dlsym", "GLIBC_2.2.5"));
}

// Per hook (hook_table.hpp), in a fixed table since lookups happen on any thread: the real
// function an application's lookup found, and the one we found ourselves when it looked nothing
// up. Ours is kept once found: the library stays loaded while the application calls through
// it, so a present costs an atomic load, not a symbol lookup.
struct Remembered {
  std::atomic<Proc> real{nullptr};
  std::atomic<const char*> via{nullptr};
  std::atomic<Proc> found{nullptr};
};
std::array<Remembered, kHookCount> remembered;

Remembered* remembered_slot(const char* name) {
  const int hook = hook_index(name);
  return hook < 0 ? nullptr : &remembered[static_cast<size_t>(hook)];
}

Proc from_loaded_library(Library library, const char* name) {
  static const char* const kGlx[] = {"libGL.so.1", "libGLX.so.0", nullptr};
  static const char* const kEgl[] = {"libEGL.so.1", nullptr};
  for (const char* const* file_name = library == Library::GLX ? kGlx : kEgl; *file_name; ++file_name) {
    const char* file = *file_name;
    // RTLD_NOLOAD: only a library the application loaded; we never bring one into its process.
    void* handle = dlopen(file, RTLD_LAZY | RTLD_NOLOAD);
    if (!handle) continue;
    void* found = real_dlsym(handle, name);
    dlclose(handle);  // NOLOAD took a reference; the application's own keeps it loaded
    if (found) return reinterpret_cast<Proc>(found);
  }
  return nullptr;
}

}  // namespace

__attribute__((no_sanitize_address, no_sanitize_undefined)) void* real_dlsym_function() {
  return reinterpret_cast<void*>(find_real_dlsym());
}

__attribute__((no_sanitize_address, no_sanitize_undefined)) void* real_dlsym(void* handle, const char* name) {
  static const DlsymFunction dlsym_function = find_real_dlsym();
  return dlsym_function ? dlsym_function(handle, name) : nullptr;
}

void remember(const char* name, Proc real, const char* via) {
  if (!real) return;
  if (Remembered* slot = remembered_slot(name)) {
    slot->real.store(real);
    slot->via.store(via);
  }
}

const char* reached_through(const char* name) {
  const Remembered* slot = remembered_slot(name);
  const char* via = slot ? slot->via.load() : nullptr;
  return via ? via : "linked";
}

Proc real_proc(Library library, const char* name) {
  Remembered* slot = remembered_slot(name);
  if (slot) {
    if (Proc real = slot->real.load()) return real;
    if (Proc found = slot->found.load(std::memory_order_acquire)) return found;
  }
  Proc found = reinterpret_cast<Proc>(real_dlsym(RTLD_NEXT, name));
  if (!found) found = from_loaded_library(library, name);
  // Not found (the library is not loaded yet) is not kept: the next call looks again.
  if (slot && found) slot->found.store(found, std::memory_order_release);
  return found;
}

}  // namespace pfx::inject
