#include <cmath>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "panels.hpp"

namespace pfx::app {
namespace {

constexpr double kDegrees = 180.0 / M_PI;

void draw_camera(ViewerSession& session, UiState& ui) {
  Camera& camera = session.source().camera();
  if (session.source().has_scene()) {
    ImGui::Text("position %.2f %.2f %.2f", camera.position.x, camera.position.y, camera.position.z);
    ImGui::Text("target   %.2f %.2f %.2f", camera.target.x, camera.target.y, camera.target.z);
    if (ImGui::Button("frame scene (F)")) ui.frame_camera = true;
    ImGui::SameLine();
    if (ImGui::Button("reset (Home)")) ui.reset_camera = true;
  } else {
    ImGui::TextDisabled("an image has no place: only the lens is used");
  }
  double fovy = camera.fovy_radians * kDegrees;
  const double fovy_min = 1, fovy_max = 170;
  if (ImGui::SliderScalar("vertical FOV", ImGuiDataType_Double, &fovy, &fovy_min, &fovy_max, "%.1f deg"))
    camera.fovy_radians = fovy / kDegrees;
  double near_plane = camera.near_plane;
  const double near_min = 1e-3, near_max = 100;
  if (ImGui::SliderScalar("near", ImGuiDataType_Double, &near_plane, &near_min, &near_max, "%.3f m",
                          ImGuiSliderFlags_Logarithmic) &&
      near_plane < camera.far_plane)
    camera.near_plane = near_plane;
  bool infinite = std::isinf(camera.far_plane);
  if (ImGui::Checkbox("infinite far plane", &infinite))
    camera.far_plane = infinite ? INFINITY : std::max(1000.0, camera.near_plane * 10);
  if (!infinite) {
    double far_plane = camera.far_plane;
    const double far_min = 0.01, far_max = 1e6;
    if (ImGui::SliderScalar("far", ImGuiDataType_Double, &far_plane, &far_min, &far_max, "%.1f m",
                            ImGuiSliderFlags_Logarithmic) &&
        far_plane > camera.near_plane)
      camera.far_plane = far_plane;
  }
}

void draw_tone(ToneMapSettings& tone) {
  const double ev_min = -10, ev_max = 10;
  ImGui::SliderScalar("exposure", ImGuiDataType_Double, &tone.exposure_ev, &ev_min, &ev_max, "%.2f EV");
  if (ImGui::BeginCombo("tone curve", tone_curve_name(tone.curve))) {
    for (const auto& name : tone_curve_names()) {
      ToneCurve curve;
      if (parse_tone_curve(name, &curve, nullptr) && ImGui::Selectable(name.c_str(), curve == tone.curve)) tone.curve = curve;
    }
    ImGui::EndCombo();
  }
}

}  // namespace

void draw_messages(const ViewerSession& session) {
  ImGui::BeginChild("messages", ImVec2(0, 110), true);
  for (const auto& message : session.messages()) {
    if (message.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", message.text.c_str());
    if (message.error) ImGui::PopStyleColor();
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
  ImGui::EndChild();
}

void draw_view_panel(ViewerSession& session, UiState& ui) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 370, 320), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, 390), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("View")) return ImGui::End();
  ImGui::Text("%s, frame %dx%d", session.source().description().c_str(), session.output_width(), session.output_height());

  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (session.output().codes())
      ImGui::TextWrapped("an 8-bit picture: shown and saved as the chain's 8-bit result, as pfx-render writes it "
                         "from a PNG (exposure and the tone curve are for HDR frames)");
    else
      draw_tone(session.tone());
  }
  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) draw_camera(session, ui);
  if (ImGui::CollapsingHeader("Preset and screenshots", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::InputText("preset", &session.preset_path());
    if (ImGui::Button("save preset")) session.save_preset();
    ImGui::SameLine();
    if (ImGui::Button("load preset")) session.load_preset();
    ImGui::SameLine();
    if (ImGui::Button("screenshot (F12)")) ui.screenshot = true;
    bool watching = session.watching();
    if (ImGui::Checkbox("reload rebuilt plugins", &watching)) session.set_watching(watching);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("checks the plugin files 10 times a second; a rebuilt plugin is reloaded with\n"
                        "its parameter values kept, and one that fails leaves the old version running");
  }
  if (ImGui::CollapsingHeader("Controls")) {
    ImGui::TextUnformatted(
        "left drag: orbit    right or middle drag, shift + left: pan\n"
        "wheel: zoom    W A S D: fly, Q E: down, up (shift: faster)\n"
        "F: frame the scene    Home: the scene's own camera    Tab: hide or show the panels\n"
        "F12: screenshot (EXR, PNG and preset)    Esc: quit");
  }
  draw_messages(session);
  ImGui::End();
}

void draw_error_overlay(const ViewerSession& session) {
  if (session.render_error().empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 10), ImGuiCond_Always, ImVec2(0.5f, 0));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("frame failed", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "frame failed: %s", session.render_error().c_str());
  ImGui::End();
}

}  // namespace pfx::app
