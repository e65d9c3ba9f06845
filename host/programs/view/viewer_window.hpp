// The viewer's window: GLFW with a GL 4.5 core context (current on this thread, GL functions of
// this program loaded) and Dear ImGui on it, through the GLFW and OpenGL 3 back-ends that Debian's
// libimgui-dev ships. Destroying it shuts ImGui down and closes the window.
#pragma once

#include <memory>
#include <string>

#include <pfx/core.h>

struct GLFWwindow;

namespace pfx::app {

class ViewerWindow {
 public:
  // Null with *error when there is no display, or no 4.5 core context can be made.
  static std::unique_ptr<ViewerWindow> create(int width, int height, const std::string& title, std::string* error);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  // The drawable size in pixels (differs from the window size on high-density screens).
  void framebuffer_size(int* width, int* height) const;
  // "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6"
  const std::string& renderer() const { return renderer_; }

  // Polls events; with wait_seconds > 0 sleeps until an event comes or the time has passed.
  void poll_events(double wait_seconds);
  void begin_ui_frame();
  // Draws the UI over what is in the back buffer.
  void draw_ui();
  void swap();

  // For libpfxhost and the plugins (matches pfx_host::get_proc_address); the context must be current.
  static pfx_gl_proc get_proc_address(void* unused, const char* name);

 private:
  ViewerWindow() = default;
  GLFWwindow* window_ = nullptr;
  bool imgui_glfw_ = false, imgui_gl_ = false;
  std::string renderer_;
};

}  // namespace pfx::app
