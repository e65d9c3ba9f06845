#include <imgui.h>
#include <imgui_stdlib.h>

#include "panels.hpp"

namespace pfx::app {

void draw_application_panel(ViewerSession& session, const AppTimingsReader& timings, const std::string& attached) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10, display.y - 300), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(display.x - 20, 290), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Application")) return ImGui::End();
  ImGui::TextWrapped("every change goes to %s, which the application applies within a second", attached.c_str());
  ImGui::InputText("preset", &session.preset_path());
  if (ImGui::Button("save preset")) session.save_preset();
  ImGui::SameLine();
  if (ImGui::Button("load preset")) session.load_preset();
  const AppTimes& times = timings.latest();
  if (timings.path().empty()) {
    ImGui::TextDisabled("no timings (--timings FILE)");
  } else if (times.frame == 0) {
    ImGui::TextDisabled("no times from the application yet");
  } else {
    ImGui::Text("the application's chain %s, frame %llu, %s", times.chain.c_str(),
                static_cast<unsigned long long>(times.frame), times.timing.c_str());
    draw_pass_table(times.times);
  }
  draw_messages(session);
  ImGui::End();
}

}  // namespace pfx::app
