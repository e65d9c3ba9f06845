#include <string>
#include <vector>

#include <imgui.h>

#include "panel_names.hpp"
#include "panels.hpp"
#include "param_widgets.hpp"

namespace pfx::app {
namespace {

std::vector<std::string> chain_effect_ids(const pfx::host::Chain& chain) {
  std::vector<std::string> ids;
  for (size_t i = 0; i < chain.size(); ++i) ids.push_back(chain.effect_id(i));
  return ids;
}

}  // namespace

void draw_chain_panel(ViewerSession& session) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(300, 130), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Chain")) return ImGui::End();
  pfx::host::Chain& chain = session.chain();
  // Changes are applied after the list is drawn, never while it is being walked.
  enum { NONE, UP, DOWN, REMOVE } action = NONE;
  size_t target = 0;
  const std::vector<std::string> names = panel_names(chain_effect_ids(chain));
  for (size_t i = 0; i < chain.size(); ++i) {
    ImGui::PushID(int(i));
    bool enabled = chain.enabled(i);
    if (ImGui::Checkbox(names[i].c_str(), &enabled)) chain.set_enabled(i, enabled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("run this effect (off: skipped at no cost)");
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 80);
    if (ImGui::ArrowButton("up", ImGuiDir_Up) && i > 0) action = UP, target = i;
    ImGui::SameLine();
    if (ImGui::ArrowButton("down", ImGuiDir_Down) && i + 1 < chain.size()) action = DOWN, target = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) action = REMOVE, target = i;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("remove from the chain (its values leave with it and later instances of its\n"
                        "effect renumber; an effect's only instance leaves its values behind)");
    ImGui::PopID();
  }
  if (chain.size() == 0) ImGui::TextDisabled("(no effect: the frame is shown as it is)");
  if (action == UP) chain.move(target, target - 1);
  if (action == DOWN) chain.move(target, target + 1);
  if (action == REMOVE) chain.remove(target);

  if (ImGui::BeginCombo("add", "effect...")) {
    for (const auto& effect : session.registry().effects()) {
      const std::string label = std::string(effect.desc->id) + "  (" + effect.plugin->id + ")";
      if (ImGui::Selectable(label.c_str())) {
        std::string error;
        if (!chain.add(effect.desc->id, &error)) session.error(error);
      }
    }
    ImGui::EndCombo();
  }
  ImGui::End();
}

void draw_parameters_panel(ViewerSession& session, UiState& ui) {
  ImGui::SetNextWindowPos(ImVec2(10, 150), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 460), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Parameters")) return ImGui::End();
  // Widgets take a bit over half the width, so labels such as "Automatic minimum size" fit.
  ImGui::PushItemWidth(ImGui::GetWindowWidth() * 0.5f);
  pfx::host::Chain& chain = session.chain();
  const std::vector<std::string> names = panel_names(chain_effect_ids(chain));
  for (size_t i = 0; i < chain.size(); ++i) {
    const pfx::host::EffectInfo* info = session.registry().find_effect(chain.effect_id(i));
    if (!info) continue;
    ImGui::PushID(int(i));
    const std::string& name = names[i];
    const std::string title = std::string(info->desc->label ? info->desc->label : info->desc->id) + "  [" + name +
                              "]" + (chain.enabled(i) ? "" : "  (off)");
    if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      if (info->desc->description && *info->desc->description && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\nplugin %s %s", info->desc->description, info->plugin->id.c_str(), info->plugin->version.c_str());
      FrameSizeParams at_frame;
      const int width = session.output_width(), height = session.output_height();
      if (width > 0 && height > 0) {
        at_frame.params = pfx::host::params_at_frame_size(*info, uint32_t(width), uint32_t(height));
        at_frame.size = std::to_string(width) + "x" + std::to_string(height);
      }
      draw_effect_parameters(*info->desc, name, session.params(), &ui.param_problem, at_frame);
    }
    ImGui::PopID();
  }
  if (!ui.param_problem.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", ui.param_problem.c_str());
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace pfx::app
