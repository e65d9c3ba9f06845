#include <string>

#include <imgui.h>

#include "panels.hpp"
#include "param_widgets.hpp"

namespace pfx::app {
namespace {

// "bloom" while the chain holds one bloom; "bloom#1", "bloom#2" once it holds more, so each
// instance shows the name --set and presets use for it ("bloom#1" and "bloom" are the same).
std::string shown_name(const pfx::host::Chain& chain, size_t index) {
  size_t same = 0;
  for (size_t i = 0; i < chain.size(); ++i) same += chain.effect_id(i) == chain.effect_id(index);
  return same > 1 ? chain.effect_id(index) + "#" + std::to_string(chain.instance_number(index)) : chain.effect_id(index);
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
  for (size_t i = 0; i < chain.size(); ++i) {
    ImGui::PushID(int(i));
    bool enabled = chain.enabled(i);
    if (ImGui::Checkbox(shown_name(chain, i).c_str(), &enabled)) chain.set_enabled(i, enabled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("run this effect (off: skipped at no cost)");
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 80);
    if (ImGui::ArrowButton("up", ImGuiDir_Up) && i > 0) action = UP, target = i;
    ImGui::SameLine();
    if (ImGui::ArrowButton("down", ImGuiDir_Down) && i + 1 < chain.size()) action = DOWN, target = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) action = REMOVE, target = i;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("remove from the chain (an effect's only instance keeps its values; a second\n"
                        "one takes its values along and the later ones renumber)");
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
  for (size_t i = 0; i < chain.size(); ++i) {
    const pfx::host::EffectInfo* info = session.registry().find_effect(chain.effect_id(i));
    if (!info) continue;
    ImGui::PushID(int(i));
    const std::string name = shown_name(chain, i);
    const std::string title = std::string(info->desc->label ? info->desc->label : info->desc->id) + "  [" + name +
                              "]" + (chain.enabled(i) ? "" : "  (off)");
    if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      if (info->desc->description && *info->desc->description && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\nplugin %s %s", info->desc->description, info->plugin->id.c_str(), info->plugin->version.c_str());
      draw_effect_parameters(*info->desc, name, session.params(), &ui.param_problem);
    }
    ImGui::PopID();
  }
  if (!ui.param_problem.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", ui.param_problem.c_str());
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace pfx::app
