// A GL 4.5 core context without a window: EGL's surfaceless platform (Mesa llvmpipe on machines
// without a GPU, the vendor driver where there is one). Used by pfx-render, pfx-bench and the tests.
#pragma once

#include <memory>
#include <string>

#include <pfx/core.h>

namespace pfx::app {

class HeadlessContext {
 public:
  // What the destructor does with the EGL display. EGL gives every caller in a process the same
  // display for the same platform, so a library running inside somebody else's program (a frei0r
  // plugin) must not terminate it: the program, or another plugin, may have contexts on it.
  enum class Display {
    OWN,    // our programs: eglTerminate when the context goes
    SHARED  // a guest in another program: only the context is destroyed
  };
  // Creates the context, makes it current on this thread and loads the GL functions of this
  // program. On failure returns null and says why in *error (no EGL, no 4.5 core context...).
  static std::unique_ptr<HeadlessContext> create(std::string* error, Display display = Display::OWN);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  // "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6"
  const std::string& renderer() const { return renderer_; }

  // The loader to hand to libpfxhost and plugins (matches pfx_host::get_proc_address).
  static pfx_gl_proc get_proc_address(void* unused, const char* name);

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  bool terminate_ = true;
  std::string renderer_;
};

}  // namespace pfx::app
