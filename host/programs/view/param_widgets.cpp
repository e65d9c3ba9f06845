#include "param_widgets.hpp"

#include <cmath>
#include <cstring>
#include <vector>

#include <imgui.h>

#include "plugin_listing.hpp"

namespace pfx::app {
namespace {

bool same_value(const pfx_value& a, const pfx_value& b, pfx_param_type type) {
  for (int i = 0; i < component_count(type); ++i)
    if (a.v[i] != b.v[i]) return false;
  return true;
}

// The slider range: the display range when it is usable, else the hard range when finite.
bool slider_range(const pfx_param_desc& d, double* lo, double* hi) {
  *lo = d.display_min;
  *hi = d.display_max;
  if (!(std::isfinite(*lo) && std::isfinite(*hi) && *lo < *hi)) *lo = d.hard_min, *hi = d.hard_max;
  if (!(std::isfinite(*lo) && std::isfinite(*hi) && *lo < *hi)) return false;
  // A logarithmic slider cannot start at or below 0.
  return !(d.flags & PFX_PARAM_LOGARITHMIC) || *lo > 0;
}

void show_tooltip(const std::string& key, const pfx_param_desc& d) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
  if (d.tooltip && *d.tooltip) ImGui::TextUnformatted(d.tooltip);
  ImGui::TextDisabled("%s  (%s)", key.c_str(), d.unit && *d.unit ? d.unit : "no unit");
  ImGui::TextDisabled("range [%g, %g], default %s%s", d.hard_min, d.hard_max, default_value_text(d).c_str(),
                      (d.flags & PFX_PARAM_REJECT_OUT_OF_RANGE) ? ", values outside are refused" : "");
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

// One widget; returns true with *value changed by the user.
bool edit_value(const pfx_param_desc& d, pfx_value* value) {
  const char* label = d.label && *d.label ? d.label : d.id;
  double lo = 0, hi = 0;
  const bool has_range = slider_range(d, &lo, &hi);
  const double* hard_lo = std::isfinite(d.hard_min) ? &d.hard_min : nullptr;
  const double* hard_hi = std::isfinite(d.hard_max) ? &d.hard_max : nullptr;
  const float speed = d.step > 0 ? float(d.step) : has_range ? float((hi - lo) / 200.0) : 0.01f;
  switch (d.type) {
    case PFX_PARAM_BOOL: {
      bool on = value->v[0] != 0;
      if (!ImGui::Checkbox(label, &on)) return false;
      value->v[0] = on ? 1.0 : 0.0;
      return true;
    }
    case PFX_PARAM_ENUM: {
      int index = int(value->v[0]);
      auto item_label = [&](int i) { return d.items[i].label && *d.items[i].label ? d.items[i].label : d.items[i].id; };
      bool changed = false;
      if (ImGui::BeginCombo(label, index >= 0 && uint32_t(index) < d.item_count ? item_label(index) : "?")) {
        for (uint32_t i = 0; i < d.item_count; ++i)
          if (ImGui::Selectable(item_label(int(i)), int(i) == index)) index = int(i), changed = true;
        ImGui::EndCombo();
      }
      if (changed) value->v[0] = index;
      return changed;
    }
    case PFX_PARAM_INT: {
      const std::string format = number_format(d, true);
      long long number = (long long)value->v[0];
      bool changed;
      if (has_range) {
        long long min = (long long)std::ceil(lo), max = (long long)std::floor(hi);
        changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &number, &min, &max, format.c_str());
      } else {
        long long min = hard_lo ? (long long)*hard_lo : 0, max = hard_hi ? (long long)*hard_hi : 0;
        changed = ImGui::DragScalar(label, ImGuiDataType_S64, &number, std::max(speed, 1.0f), hard_lo ? &min : nullptr,
                                    hard_hi ? &max : nullptr, format.c_str());
      }
      if (changed) value->v[0] = double(number);
      return changed;
    }
    case PFX_PARAM_FLOAT: {
      const std::string format = number_format(d, false);
      if (has_range) {
        ImGuiSliderFlags flags = (d.flags & PFX_PARAM_LOGARITHMIC) ? ImGuiSliderFlags_Logarithmic : 0;
        return ImGui::SliderScalar(label, ImGuiDataType_Double, &value->v[0], &lo, &hi, format.c_str(), flags);
      }
      return ImGui::DragScalar(label, ImGuiDataType_Double, &value->v[0], speed, hard_lo, hard_hi, format.c_str());
    }
    case PFX_PARAM_COLOR: {
      float rgb[3] = {float(value->v[0]), float(value->v[1]), float(value->v[2])};
      // Linear, scene-referred colour: components above 1 are allowed.
      if (!ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) return false;
      for (int i = 0; i < 3; ++i) value->v[i] = rgb[i];
      return true;
    }
    case PFX_PARAM_VEC2:
    case PFX_PARAM_VEC3:
      return ImGui::DragScalarN(label, ImGuiDataType_Double, value->v, component_count(d.type), speed, hard_lo, hard_hi,
                                number_format(d, false).c_str());
  }
  return false;
}

}  // namespace

std::string number_format(const pfx_param_desc& param, bool integer) {
  std::string format = integer ? "%lld" : "%.3f";
  if (param.unit && *param.unit) {
    format += " ";
    for (const char* c = param.unit; *c; ++c) format += *c == '%' ? std::string("%%") : std::string(1, *c);
  }
  return format;
}

bool draw_effect_parameters(const pfx_effect_desc& effect, const std::string& instance, pfx::host::ParamStore& params,
                            std::string* problem, const FrameSizeParams& at_frame) {
  const pfx_value* values = params.values(instance);
  if (!values) return false;
  if (effect.param_count == 0) ImGui::TextDisabled("(no parameters)");
  // Groups in order of first appearance; parameters without a group first, outside any node.
  std::vector<std::string> groups = {""};
  for (uint32_t i = 0; i < effect.param_count; ++i) {
    const std::string group = effect.params[i].group ? effect.params[i].group : "";
    bool known = false;
    for (const auto& g : groups) known |= g == group;
    if (!known) groups.push_back(group);
  }
  bool changed = false;
  for (const auto& group : groups) {
    if (!group.empty() && !ImGui::TreeNodeEx(group.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
    for (uint32_t i = 0; i < effect.param_count; ++i) {
      const pfx_param_desc& d = effect.params[i];
      if (group != (d.group ? d.group : "")) continue;
      const std::string key = instance + "." + d.id;
      ImGui::PushID(key.c_str());
      // A parameter that follows the frame size shows its range at the frame being rendered, and,
      // while it is at its listed default (not set), the default the effect runs with there.
      const bool follows = (d.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) && at_frame.params.size() == effect.param_count;
      const pfx_param_desc& shown = follows ? at_frame.params[i] : d;
      const bool unset = same_value(values[i], d.default_value, d.type);
      pfx_value value = follows && unset ? shown.default_value : values[i];
      if (edit_value(shown, &value)) {
        std::string error;
        if (params.set_value(instance, d.id, value, &error)) problem->clear(), changed = true;
        else *problem = error;
        values = params.values(instance);
      }
      show_tooltip(key, shown);
      if (follows && ImGui::IsItemHovered())
        ImGui::SetTooltip("default and range follow the frame size: %s at %s", default_value_text(shown).c_str(),
                          at_frame.size.c_str());
      if (!unset) {
        ImGui::SameLine();
        if (ImGui::SmallButton("reset")) {
          params.reset(instance, d.id);
          values = params.values(instance);
          changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the default, %s", default_value_text(shown).c_str());
      }
      ImGui::PopID();
    }
    if (!group.empty()) ImGui::TreePop();
  }
  return changed;
}

}  // namespace pfx::app
