// The viewer's panels, drawn with Dear ImGui each frame. None of them knows any plugin: the
// parameter panel is made from the descriptors, the timing panel from the chain's report.
#pragma once

#include <string>

#include "app_timings.hpp"
#include "viewer_session.hpp"

namespace pfx::app {

// What the panels and the main loop share besides the session.
struct UiState {
  bool show_panels = true;   // Tab hides them to see the whole picture
  bool continuous = false;   // render every frame (for live timings), not only on change
  double frame_ms = 0;       // the whole loop, UI included, smoothed
  std::string param_problem;  // the last refused parameter change
  bool frame_camera = false, reset_camera = false, screenshot = false;  // requests from buttons
};

// Effects in order: on/off, up/down, remove, add.
void draw_chain_panel(ViewerSession& session);
// One collapsing header per instance in the chain, its parameters inside; the title names the
// instance ("bloom#2") when the chain holds more than one of its effect.
void draw_parameters_panel(ViewerSession& session, UiState& ui);
// Per-pass times, frame time, peak target memory, skipped effects, the effects' own figures.
void draw_timing_panel(ViewerSession& session, UiState& ui);
// A table of pass times (effect, pass, ms) and their total.
void draw_pass_table(const pfx::host::FrameTimes& times);
// Attached to an application's chain (--attach): the preset it watches, save and load of the
// user's preset, the application's per-pass times, the messages.
void draw_application_panel(ViewerSession& session, const AppTimingsReader& timings, const std::string& attached);
// Input, display, camera, presets, screenshots, hot reload, messages and the controls.
void draw_view_panel(ViewerSession& session, UiState& ui);
// The session's messages, newest last, errors in red, in a scrolling box.
void draw_messages(const ViewerSession& session);
// A red line at the top while frames fail.
void draw_error_overlay(const ViewerSession& session);

}  // namespace pfx::app
