#include "attach_loop.hpp"

#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include "app_timings.hpp"
#include "exit_codes.hpp"
#include "panels.hpp"
#include "signals.hpp"
#include "viewer_session.hpp"
#include "viewer_window.hpp"

namespace pfx::app {
namespace {

// A panel beside the application rather than a picture: narrow and tall unless --window says.
constexpr int kPanelWidth = 480, kPanelHeight = 760;

// "bloom/bright 0.412 ms, bloom/composite 0.2 ms": the times as one line, for scripts.
std::string times_line(const AppTimes& times) {
  std::string line;
  for (const auto& pass : times.times.passes) {
    char ms[32];
    std::snprintf(ms, sizeof ms, " %.3f ms", pass.ms);
    line += (line.empty() ? "" : ", ") + pass.effect + "/" + pass.pass + ms;
  }
  return line;
}

}  // namespace

int run_attached(const ViewOptions& options) {
  install_viewer_signal_handlers();
  std::string message;
  auto window = ViewerWindow::create(options.window_given ? options.window_width : kPanelWidth,
                                     options.window_given ? options.window_height : kPanelHeight,
                                     "pfx-view: " + options.attach, &message);
  if (!window) {
    std::fprintf(stderr, "pfx-view: %s\n", message.c_str());
    return exit_code::kInternal;
  }
  int code = exit_code::kOk;
  auto session = ViewerSession::create(
      options, window->renderer(), [](const char* name) { return ViewerWindow::get_proc_address(nullptr, name); },
      &message, &code);
  if (!session) {
    std::fprintf(stderr, "pfx-view: %s\n", message.c_str());
    return code;
  }
  session->info("attached to " + options.attach);
  AppTimingsReader timings(options.timings);
  UiState ui;
  // What the file holds: the look it was read as (written again only once something changes).
  uint64_t written = session->state_stamp(0, 0);
  const bool scripted = options.frames > 0;
  long long frame = 0;
  while (!window->should_close() && !quit_signalled()) {
    window->poll_events(scripted ? 0.0 : 0.1);
    const double now = glfwGetTime();
    session->poll_plugins(now);
    timings.poll(now);
    ++frame;
    session->apply_edits(options.edits, frame);
    window->begin_ui_frame();
    draw_chain_panel(*session);
    draw_parameters_panel(*session, ui);
    draw_application_panel(*session, timings, options.attach);
    const uint64_t stamp = session->state_stamp(0, 0);
    if (stamp != written) {
      if (write_preset(options.attach, session->current_preset(), &message)) written = stamp;
      else session->error(message);
    }
    int width = 0, height = 0;
    window->framebuffer_size(&width, &height);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    window->draw_ui();
    window->swap();
    if (scripted && frame >= options.frames) break;
  }
  if (scripted && timings.latest().frame)
    session->info("the application's pass times (frame " + std::to_string(timings.latest().frame) +
                  "): " + times_line(timings.latest()));
  return exit_code::kOk;
}

}  // namespace pfx::app
