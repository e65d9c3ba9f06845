// The functions libpfxinject.so puts in front of the application's: the present calls, the
// lookups an application can reach them through, and context destruction. Each hands its work to
// the Injector and then calls the real function; nothing here can fail the application's call.
// Their names are listed once, in hook_table.hpp; only they and dlsym leave the library
// (exports.map).
#include <dlfcn.h>

#include <cstring>

#include "hook_table.hpp"
#include "injector.hpp"
#include "real_symbols.hpp"

using pfx::inject::Hook;
using pfx::inject::Injector;
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

// The application's function behind one of ours.
template <typename Function>
Function real(Hook hook) {
  const auto& name = pfx::inject::hook_name(hook);
  return reinterpret_cast<Function>(pfx::inject::real_proc(name.library, name.name));
}

// Our function for a name an application looks up, or null for every other name.
Proc ours(const char* name) {
  static const Proc functions[] = {
#define PFX_INJECT_OUR_FUNCTION(function, library) reinterpret_cast<Proc>(&function),
      PFX_INJECT_HOOKS(PFX_INJECT_OUR_FUNCTION)
#undef PFX_INJECT_OUR_FUNCTION
  };
  const int hook = pfx::inject::hook_index(name);
  return hook < 0 ? nullptr : functions[hook];
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

// What every present hook does: the injector runs the chain before the real present and hears
// after it. `swap(chain_ran)` calls the real present; `found` says whether there is one (else
// `none` is returned and nothing happens). A present reached again from within goes straight on.
template <typename Result, typename Swap>
Result present(const PresentCall& call, bool found, Result none, const Swap& swap) {
  if (!found) return none;
  if (presenting) return swap(false);
  PresentingFlag flag;
  Injector& injector = Injector::instance();
  injector.before_present(call);
  const Result result = swap(true);
  injector.after_present();
  return result;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void glXSwapBuffers(void* display, unsigned long drawable) {
  auto swap = real<GlxSwap>(Hook::glXSwapBuffers);
  present(PresentCall{WindowSystem::GLX, display, drawable}, swap != nullptr, 0, [&](bool) {
    swap(display, drawable);
    return 0;
  });
}

__attribute__((visibility("default"))) Proc glXGetProcAddressARB(const unsigned char* name) {
  auto lookup = real<GetProc>(Hook::glXGetProcAddressARB);
  return swap_in(reinterpret_cast<const char*>(name), lookup ? lookup(name) : nullptr, "glXGetProcAddressARB");
}

__attribute__((visibility("default"))) Proc glXGetProcAddress(const unsigned char* name) {
  auto lookup = real<GetProc>(Hook::glXGetProcAddress);
  return swap_in(reinterpret_cast<const char*>(name), lookup ? lookup(name) : nullptr, "glXGetProcAddress");
}

__attribute__((visibility("default"))) void glXDestroyContext(void* display, void* context) {
  Injector::instance().context_destroyed(WindowSystem::GLX, context);
  if (auto destroy = real<GlxDestroy>(Hook::glXDestroyContext)) destroy(display, context);
}

__attribute__((visibility("default"))) unsigned eglSwapBuffers(void* display, void* surface) {
  auto swap = real<EglSwap>(Hook::eglSwapBuffers);
  return present(PresentCall{WindowSystem::EGL, display, reinterpret_cast<unsigned long>(surface)}, swap != nullptr,
                 0u, [&](bool) { return swap(display, surface); });
}

__attribute__((visibility("default"))) unsigned eglSwapBuffersWithDamageKHR(void* display, void* surface, int* rects,
                                                                             int count) {
  auto swap = real<EglSwapWithDamage>(Hook::eglSwapBuffersWithDamageKHR);
  return present(PresentCall{WindowSystem::EGL, display, reinterpret_cast<unsigned long>(surface)}, swap != nullptr,
                 0u, [&](bool chain_ran) {
                   // The chain changed the whole frame, so the damage is then the whole surface.
                   return chain_ran ? swap(display, surface, nullptr, 0) : swap(display, surface, rects, count);
                 });
}

__attribute__((visibility("default"))) Proc eglGetProcAddress(const char* name) {
  auto lookup = real<EglGetProc>(Hook::eglGetProcAddress);
  return swap_in(name, lookup ? lookup(name) : nullptr, "eglGetProcAddress");
}

__attribute__((visibility("default"))) unsigned eglDestroyContext(void* display, void* context) {
  Injector::instance().context_destroyed(WindowSystem::EGL, context);
  auto destroy = real<EglDestroy>(Hook::eglDestroyContext);
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
  if (pfx::inject::hook_index(name) < 0) return found;
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
