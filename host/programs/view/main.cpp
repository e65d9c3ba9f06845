// pfx-view: the interactive viewer. A GLFW window shows the demo scene or an image through a chain
// of pfx effects, with Dear ImGui panels made from the plugins' parameter metadata, timings, hot
// reload of rebuilt plugins, screenshots and presets. --frames N makes it a scripted renderer.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "attach_loop.hpp"
#include "camera_controller.hpp"
#include "camera_input.hpp"
#include "display_pass.hpp"
#include "exit_codes.hpp"
#include "frame_files.hpp"
#include "panels.hpp"
#include "preset.hpp"
#include "signals.hpp"
#include "view_options.hpp"
#include "viewer_session.hpp"
#include "viewer_window.hpp"

using namespace pfx::app;
using namespace pfx::exit_code;

namespace {

int error_exit(int code, const std::string& message) {
  std::fprintf(stderr, "pfx-view: %s\n", message.c_str());
  return code;
}

// Keys that act whatever the mouse is over (unless a text field has the keyboard).
void handle_keys(ViewerWindow& window, UiState& ui) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) ui.screenshot = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) ui.frame_camera = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) ui.reset_camera = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) ui.show_panels = !ui.show_panels;
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) window.request_close();
}

void update_camera(ViewerSession& session, UiState& ui, const CameraInputSettings& settings, int frame_width,
                   int frame_height, double dt) {
  FrameSource& source = session.source();
  if (ui.reset_camera) source.camera() = source.initial_camera();
  if (source.has_scene()) {
    apply_camera_input(&source.camera(), settings, frame_height, dt);
    if (ui.frame_camera) {
      const Scene& scene = *source.scene();
      frame_box(&source.camera(), glm::dvec3(scene.bounds_min), glm::dvec3(scene.bounds_max),
                double(frame_width) / double(frame_height));
    }
  }
  ui.reset_camera = ui.frame_camera = false;
}

// A scripted frame starts no sooner than 1/60 s after the one before, as a display at 60 Hz shows
// them: what an effect does after a while of wall time (FX programs specialised for values that
// held still for half a second) has happened 30 frames later at the latest.
void wait_for_next_scripted_frame(double* last_start) {
  const double due = *last_start + 1.0 / 60.0;
  if (glfwGetTime() < due) std::this_thread::sleep_for(std::chrono::duration<double>(due - glfwGetTime()));
  *last_start = glfwGetTime();
}

// The frame on screen, fitted to the window: linear light through exposure and tone, or an 8-bit
// picture's codes as they are.
void show_output(const DisplayPass& display, ViewerSession& session, int window_width, int window_height) {
  const Viewport shown = fit_viewport(session.output_width(), session.output_height(), window_width, window_height);
  if (session.output().codes())
    display.draw_codes(session.output().shown(), shown, window_width, window_height);
  else
    display.draw(session.output().shown(), shown, window_width, window_height, session.tone());
}

int run(const ViewOptions& options) {
  install_viewer_signal_handlers();
  std::string message;
  auto window = ViewerWindow::create(options.window_width, options.window_height, "pfx-view", &message);
  if (!window) return error_exit(kInternal, message);
  int code = kOk;
  auto session = ViewerSession::create(
      options, window->renderer(), [](const char* name) { return ViewerWindow::get_proc_address(nullptr, name); },
      &message, &code);
  if (!session) return error_exit(code, message);
  DisplayPass display;
  if (!display.ok()) return error_exit(kInternal, "the display shader failed to build");

  UiState ui;
  ui.show_panels = !options.hide_panels;
  CameraInputSettings camera_settings;
  if (const Scene* scene = session->source().scene())
    camera_settings.fly_metres_per_second = std::max(0.5, 0.15 * double(glm::length(scene->bounds_max - scene->bounds_min)));
  const bool scripted = options.frames > 0;
  const double start = glfwGetTime();
  double last = start, last_scripted = start;
  uint64_t shown_stamp = 0;
  bool have_frame = false;
  long long frames_done = 0, frames_shown = 0;
  bool input_active = false;  // a button or a fly key held: keep frames coming without waiting
  using Clock = std::chrono::steady_clock;

  while (!window->should_close()) {
    // Idle, the loop sleeps until input comes (or 0.1 s passes, to check the plugin files).
    window->poll_events(scripted || ui.continuous || input_active ? 0.0 : 0.1);
    if (quit_signalled()) break;
    const Clock::time_point work_start = Clock::now();
    const double now = glfwGetTime(), dt = now - last;
    last = now;
    session->poll_plugins(now);
    int window_width = 0, window_height = 0;
    window->framebuffer_size(&window_width, &window_height);
    if (window_width < 1 || window_height < 1) continue;  // minimised
    const int width = options.size_given ? options.width : window_width;
    const int height = options.size_given ? options.height : window_height;

    window->begin_ui_frame();
    handle_keys(*window, ui);
    input_active = ImGui::IsAnyMouseDown();
    for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
      input_active |= ImGui::IsKeyDown(key);
    update_camera(*session, ui, camera_settings, width, height, dt);
    if (ui.show_panels) {
      draw_chain_panel(*session);
      draw_parameters_panel(*session, ui);
      draw_timing_panel(*session, ui);
      draw_view_panel(*session, ui);
    }
    draw_error_overlay(*session);

    if (scripted) {
      if (frames_done > 0) wait_for_next_scripted_frame(&last_scripted);
      session->apply_edits(options.edits, frames_done + 1);
    }
    const uint64_t stamp = session->state_stamp(width, height);
    if (scripted || ui.continuous || !have_frame || stamp != shown_stamp) {
      const double time = scripted ? double(frames_done) / 60.0 : now - start;
      bool ok = session->render(width, height, time, scripted);
      if (scripted && !ok) return error_exit(kEffectError, session->render_error());
      shown_stamp = stamp;
      if (!have_frame) session->info("ready: " + session->source().description());
      have_frame = true;
    }
    show_output(display, *session, window_width, window_height);
    window->draw_ui();
    if (ui.screenshot || screenshot_signalled()) session->take_screenshot();
    ui.screenshot = false;

    if (scripted && ++frames_done >= options.frames) {
      if (!options.screenshot.empty() && !session->write_frame(options.screenshot, &message)) return error_exit(kInternal, message);
      if (!options.window_shot.empty() && !write_window_png(window_width, window_height, options.window_shot, &message))
        return error_exit(kInternal, message);
      break;
    }
    window->swap();
    const double work_ms = std::chrono::duration<double, std::milli>(Clock::now() - work_start).count();
    // The first frames compile every shader: leave them out of the average.
    ++frames_shown;
    ui.frame_ms = frames_shown <= 2 ? work_ms : 0.9 * ui.frame_ms + 0.1 * work_ms;
  }
  if (!options.save_preset.empty() && !write_preset(options.save_preset, session->current_preset(), &message))
    return error_exit(kInternal, message);
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  ViewOptions options;
  std::string error;
  if (!parse_view_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-view: %s\n\n%s", error.c_str(), view_usage().c_str());
    return kUsage;
  }
  if (options.help) {
    std::fputs(view_usage().c_str(), stdout);
    return kOk;
  }
  try {
    return options.attach.empty() ? run(options) : run_attached(options);
  } catch (const std::exception& e) {
    return error_exit(kInternal, std::string("internal error: ") + e.what());
  }
}
