#include <imgui.h>

#include <nlohmann/json.hpp>

#include "panels.hpp"

namespace pfx::app {
namespace {

// An effect's report_json members as "key: value" lines, whatever the effect reports.
void draw_effect_figures(const std::string& effect, const std::string& members) {
  auto figures = nlohmann::json::parse("{" + members + "}", nullptr, false);
  if (!ImGui::TreeNodeEx(effect.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (figures.is_discarded() || !figures.is_object()) {
    ImGui::TextWrapped("%s", members.c_str());
  } else {
    for (const auto& [key, value] : figures.items()) {
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      ImGui::Text("%s: %s", key.c_str(), text.c_str());
    }
  }
  ImGui::TreePop();
}

}  // namespace

void draw_pass_table(const pfx::host::FrameTimes& times) {
  if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("effect");
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("ms");
    ImGui::TableHeadersRow();
    for (const auto& pass : times.passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(pass.effect.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(pass.pass.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%8.3f", pass.ms);
    }
    ImGui::EndTable();
  }
  ImGui::Text("total %.3f ms over %zu passes", times.total_ms, times.passes.size());
}

void draw_timing_panel(ViewerSession& session, UiState& ui) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 370, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, 300), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Timing")) return ImGui::End();
  const pfx::host::FrameReport& report = session.chain().report();
  ImGui::TextWrapped("%s", session.renderer().c_str());
  ImGui::Text("frame %.1f ms (%.1f fps), inputs + chain %.1f ms", ui.frame_ms, ui.frame_ms > 0 ? 1000.0 / ui.frame_ms : 0.0,
              session.last_render_ms());
  ImGui::Checkbox("render every frame", &ui.continuous);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("off: a frame is rendered only when something changes, so the times below are\n"
                      "those of the last change; on: every frame, for live times (costs a full core)");
  // GPU timestamps arrive frames later: say which frame the times below were measured in.
  const pfx::host::FrameTimes& times = report.times;
  if (times.frame == 0) ImGui::Text("pass times: %s, none complete yet", report.timing.c_str());
  else if (times.frame == report.frame) ImGui::Text("pass times: %s, this frame", report.timing.c_str());
  else
    ImGui::Text("pass times: %s, %llu frame(s) ago", report.timing.c_str(),
                static_cast<unsigned long long>(report.frame - times.frame));
  draw_pass_table(times);
  ImGui::Text("peak target memory %llu bytes (%.2f MiB)", static_cast<unsigned long long>(report.peak_target_bytes),
              double(report.peak_target_bytes) / (1024.0 * 1024.0));
  ImGui::TextDisabled("without pooling %llu bytes", static_cast<unsigned long long>(report.unpooled_target_bytes));
  if (!report.effects_skipped.empty()) {
    std::string skipped;
    for (const auto& id : report.effects_skipped) skipped += (skipped.empty() ? "" : ", ") + id;
    ImGui::TextWrapped("skipped (off or no-op): %s", skipped.c_str());
  }
  for (const auto& [effect, members] : report.effect_reports) draw_effect_figures(effect, members);
  ImGui::End();
}

}  // namespace pfx::app
