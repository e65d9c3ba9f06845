// The functions libpfxinject.so puts in front of the application's: the present calls, the
// lookups an application can reach them through, and context destruction. Each hands its work to
// the Injector and then calls the real function; nothing here can fail the application's call.
// Only these symbols leave the library (exports.map).
#include <dlfcn.h>

#include <cstring>

#include "injector.hpp"
#include "real_symbols.hpp"

using pfx::inject::Injector;
using pfx::inject::Library;
using pfx::inject::Proc;
using pfx::inject::PresentCall;
using pfx::inject::WindowSystem;

// Our own declarations, not GL/glx.h and EGL/egl.h: the interposers need only the calling
// convention, and the library should not need X11's headers to build.
extern "C" {
void glXSwapBuffers(void* display, unsigned long drawable);
Proc glXGetProcAddressARB(const unsigned char* name);
Proc glXGetProcAddress(const unsigned char* name);
void glXDestroyContext(void* display, void* context);
unsigned eglSwapBuffers(void* display, void* surface);
unsigned eglSwapBuffersWithDamageKHR(void* display, void* surface, int* rects, int count);
Proc eglGetProcAddress(const char* name);
unsigned eglDestroyContext(void* display, void* context);
}

namespace {

using GlxSwap = void (*)(void*, unsigned long);
using GlxDestroy = void (*)(void*, void*);
using GetProc = Proc (*)(const unsigned char*);
using EglSwap = unsigned (*)(void*, void*);
using EglSwapWithDamage = unsigned (*)(void*, void*, int*, int);
using EglGetProc = Proc (*)(const char*);
using EglDestroy = unsigned (*)(void*, void*);

template <typename Function>
Function real(Library library, const char* name) {
  return reinterpret_cast<Function>(pfx::inject::real_proc(library, name));
}

// Our function for a name an application looks up, or null for every other name.
Proc ours(const char* name) {
  struct Hook {
    const char* name;
    Proc function;
  };
  static const Hook hooks[] = {
      {"glXSwapBuffers", reinterpret_cast<Proc>(&glXSwapBuffers)},
      {"glXGetProcAddressARB", reinterpret_cast<Proc>(&glXGetProcAddressARB)},
      {"glXGetProcAddress", reinterpret_cast<Proc>(&glXGetProcAddress)},
      {"glXDestroyContext", reinterpret_cast<Proc>(&glXDestroyContext)},
      {"eglSwapBuffers", reinterpret_cast<Proc>(&eglSwapBuffers)},
      {"eglSwapBuffersWithDamageKHR", reinterpret_cast<Proc>(&eglSwapBuffersWithDamageKHR)},
      {"eglGetProcAddress", reinterpret_cast<Proc>(&eglGetProcAddress)},
      {"eglDestroyContext", reinterpret_cast<Proc>(&eglDestroyContext)},
  };
  if (!name) return nullptr;
  for (const auto& hook : hooks)
    if (std::strcmp(hook.name, name) == 0) return hook.function;
  return nullptr;
}

// Whether `name` is one we hand out our own function for. Not instrumented, like every step of a
// lookup of another name: AddressSanitizer's runtime finds the functions it wraps with dlsym while
// it starts, before instrumented code may run.
constexpr const char* kHookedNames[] = {"glXSwapBuffers",       "glXGetProcAddressARB",         "glXGetProcAddress",
                                        "glXDestroyContext",    "eglSwapBuffers",               "eglSwapBuffersWithDamageKHR",
                                        "eglGetProcAddress",    "eglDestroyContext"};

__attribute__((no_sanitize_address, no_sanitize_undefined)) bool is_hooked_name(const char* name) {
  if (!name) return false;
  for (const char* hooked : kHookedNames) {
    size_t i = 0;
    while (hooked[i] && hooked[i] == name[i]) ++i;
    if (hooked[i] == name[i]) return true;
  }
  return false;
}

// A lookup found `found` for `name`: when it is one of ours, remember the real one and hand out
// ours instead. A lookup that found our own function (RTLD_DEFAULT sees us first) is not a real one.
Proc swap_in(const char* name, Proc found, const char* via) {
  Proc hook = ours(name);
  if (!hook || !found) return found;
  if (found != hook) pfx::inject::remember(name, found, via);
  return hook;
}

// Whether a return address lies in the GL stack itself (glvnd's libGL, libGLX, libEGL, their
// dispatch library, Mesa's drivers): those look their own functions up by name, and must get
// them, not ours, or one present would run through us twice.
bool inside_gl_libraries(void* address) {
  Dl_info info{};
  if (!address || !dladdr(address, &info) || !info.dli_fname) return false;
  const char* slash = std::strrchr(info.dli_fname, '/');
  const char* file = slash ? slash + 1 : info.dli_fname;
  for (const char* prefix : {"libGL", "libEGL", "libgallium", "libglapi"})
    if (std::strncmp(file, prefix, std::strlen(prefix)) == 0) return true;
  return std::strstr(file, "_dri") != nullptr;
}

// Set while this thread is inside one of our present hooks: a present reached again from within
// (a driver calling back through the public symbol) goes straight to the real function.
thread_local bool presenting = false;

class PresentingFlag {
 public:
  PresentingFlag() { presenting = true; }
  ~PresentingFlag() { presenting = false; }
};

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void glXSwapBuffers(void* display, unsigned long drawable) {
  auto swap = real<GlxSwap>(Library::GLX, "glXSwapBuffers");
  if (!swap) return;
  if (presenting) return swap(display, drawable);
  PresentingFlag flag;
  Injector& injector = Injector::instance();
  injector.before_present(PresentCall{WindowSystem::GLX, display, drawable});
  swap(display, drawable);
  injector.after_present();
}

__attribute__((visibility("default"))) Proc glXGetProcAddressARB(const unsigned char* name) {
  auto lookup = real<GetProc>(Library::GLX, "glXGetProcAddressARB");
  return swap_in(reinterpret_cast<const char*>(name), lookup ? lookup(name) : nullptr, "glXGetProcAddressARB");
}

__attribute__((visibility("default"))) Proc glXGetProcAddress(const unsigned char* name) {
  auto lookup = real<GetProc>(Library::GLX, "glXGetProcAddress");
  return swap_in(reinterpret_cast<const char*>(name), lookup ? lookup(name) : nullptr, "glXGetProcAddress");
}

__attribute__((visibility("default"))) void glXDestroyContext(void* display, void* context) {
  Injector::instance().context_destroyed(WindowSystem::GLX, context);
  if (auto destroy = real<GlxDestroy>(Library::GLX, "glXDestroyContext")) destroy(display, context);
}

__attribute__((visibility("default"))) unsigned eglSwapBuffers(void* display, void* surface) {
  auto swap = real<EglSwap>(Library::EGL, "eglSwapBuffers");
  if (!swap) return 0;
  if (presenting) return swap(display, surface);
  PresentingFlag flag;
  Injector& injector = Injector::instance();
  injector.before_present(PresentCall{WindowSystem::EGL, display, reinterpret_cast<unsigned long>(surface)});
  const unsigned result = swap(display, surface);
  injector.after_present();
  return result;
}

__attribute__((visibility("default"))) unsigned eglSwapBuffersWithDamageKHR(void* display, void* surface, int* rects,
                                                                             int count) {
  auto swap = real<EglSwapWithDamage>(Library::EGL, "eglSwapBuffersWithDamageKHR");
  if (!swap) return 0;
  if (presenting) return swap(display, surface, rects, count);
  PresentingFlag flag;
  Injector& injector = Injector::instance();
  injector.before_present(PresentCall{WindowSystem::EGL, display, reinterpret_cast<unsigned long>(surface)});
  // The chain changed the whole frame, so the damage is the whole surface.
  const unsigned result = swap(display, surface, nullptr, 0);
  (void)rects;
  (void)count;
  injector.after_present();
  return result;
}

__attribute__((visibility("default"))) Proc eglGetProcAddress(const char* name) {
  auto lookup = real<EglGetProc>(Library::EGL, "eglGetProcAddress");
  return swap_in(name, lookup ? lookup(name) : nullptr, "eglGetProcAddress");
}

__attribute__((visibility("default"))) unsigned eglDestroyContext(void* display, void* context) {
  Injector::instance().context_destroyed(WindowSystem::EGL, context);
  auto destroy = real<EglDestroy>(Library::EGL, "eglDestroyContext");
  return destroy ? destroy(display, context) : 0;
}

// glmark2, GLFW and SDL open libGL or libEGL themselves and look the present call up by name.
// dlsym's entry (below) comes here for every handle but RTLD_NEXT, by a jump, so the return
// address is still the application's.
static __attribute__((noinline)) void* hand_out(void* found, const char* name, void* caller) {
  if (inside_gl_libraries(caller)) return found;
  return reinterpret_cast<void*>(swap_in(name, reinterpret_cast<Proc>(found), "dlsym"));
}

__attribute__((visibility("hidden"), no_sanitize_address, no_sanitize_undefined)) void* pfx_inject_dlsym_hooked(
    void* handle, const char* name) {
  void* found = pfx::inject::real_dlsym(handle, name);
  if (!is_hooked_name(name)) return found;
  return hand_out(found, name, __builtin_return_address(0));
}

__attribute__((visibility("hidden"))) void* pfx_inject_real_dlsym = nullptr;

// Runs at the first dlsym(RTLD_NEXT, ...), which may come from a sanitizer runtime still starting.
__attribute__((visibility("hidden"), no_sanitize_address, no_sanitize_undefined)) void* pfx_inject_resolve_real_dlsym() {
  pfx_inject_real_dlsym = pfx::inject::real_dlsym_function();
  return pfx_inject_real_dlsym;
}

}  // extern "C"

// dlsym(RTLD_NEXT, name) means "the next definition after the caller's library", and the C
// library finds the caller from its return address. Other preloaded libraries (libfaketime,
// for one) rely on it, so those calls must reach the real dlsym with the caller's return address
// untouched: a tail jump, which C++ cannot promise, hence these few instructions. Every other
// handle jumps to pfx_inject_dlsym_hooked.
#if defined(__x86_64__)
asm(R"(
    .text
    .globl dlsym
    .type dlsym, @function
dlsym:
    cmpq $-1, %rdi
    jne pfx_inject_dlsym_hooked
    movq pfx_inject_real_dlsym(%rip), %rax
    testq %rax, %rax
    jz 1f
    jmp *%rax
1:  pushq %rdi
    pushq %rsi
    subq $8, %rsp
    call pfx_inject_resolve_real_dlsym
    addq $8, %rsp
    popq %rsi
    popq %rdi
    jmp *%rax
    .size dlsym, .-dlsym
)");
#else
#error "libpfxinject's dlsym entry is written for x86-64; port its dozen instructions to this architecture"
#endif
