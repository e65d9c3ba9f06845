#include "fx_parameters.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <set>

namespace pfx_fx {

using pfx::fx::annotation_number;
using pfx::fx::annotation_string;
using pfx::fx::BaseType;
using pfx::fx::UniformInfo;

const char* ParamTable::keep(const std::string& text) {
  strings.push_back(std::make_unique<std::string>(text));
  return strings.back()->c_str();
}

namespace {

// The smallest and largest component of a vector annotation, or the fallback.
double annotation_min(const pfx::fx::Annotations& a, const std::string& name, double fallback) {
  auto it = a.find(name);
  if (it == a.end() || it->second.is_string || it->second.components.empty()) return fallback;
  return *std::min_element(it->second.components.begin(), it->second.components.end());
}
double annotation_max(const pfx::fx::Annotations& a, const std::string& name, double fallback) {
  auto it = a.find(name);
  if (it == a.end() || it->second.is_string || it->second.components.empty()) return fallback;
  return *std::max_element(it->second.components.begin(), it->second.components.end());
}

// ui_items: labels separated by '\0'.
std::vector<std::string> split_items(const std::string& text) {
  std::vector<std::string> items;
  std::string current;
  for (char c : text) {
    if (c == '\0') items.push_back(current), current.clear();
    else current += c;
  }
  if (!current.empty()) items.push_back(current);
  return items;
}

class Builder {
 public:
  Builder(const pfx::fx::EffectModel& model, ParamTable& table) : model_(model), t_(table) {}

  void uniform(int index, std::vector<std::string>& warnings) {
    const UniformInfo& u = model_.uniforms[static_cast<std::size_t>(index)];
    if (!u.source.empty()) return;  // the runtime fills it (timer, framecount, ...)
    const auto& a = u.annotations;
    const pfx::fx::Type& type = u.type;
    if (type.is_array() || type.is_matrix()) {
      warnings.push_back("uniform '" + u.name + "' (" + pfx::fx::type_name(type) + ") is not offered as a parameter; it keeps its initial value");
      return;
    }
    std::string ui_type = annotation_string(a, "ui_type");
    int n = type.components();
    bool whole = type.base == BaseType::kInt || type.base == BaseType::kUint;
    if (type.base == BaseType::kBool) {
      for (int c = 0; c < n; ++c) add(u, index, c, 1, PFX_PARAM_BOOL, n > 1 ? "xyzw"[c] : 0);
      return;
    }
    std::vector<std::string> labels = split_items(annotation_string(a, "ui_items"));
    if (n == 1 && whole && !labels.empty() && (ui_type == "combo" || ui_type == "radio" || ui_type == "list" || ui_type.empty())) {
      add(u, index, 0, 1, PFX_PARAM_ENUM, 0, labels);
      return;
    }
    if (n == 1) return add(u, index, 0, 1, whole ? PFX_PARAM_INT : PFX_PARAM_FLOAT, 0);
    bool color = ui_type == "color";
    if (n == 2) return add(u, index, 0, 2, PFX_PARAM_VEC2, 0);
    add(u, index, 0, 3, color && !whole ? PFX_PARAM_COLOR : PFX_PARAM_VEC3, n == 4 ? 'r' : 0);
    if (n == 4) add(u, index, 3, 1, whole ? PFX_PARAM_INT : PFX_PARAM_FLOAT, color ? 'a' : 'w');
  }

 private:
  std::string unique_id(const std::string& base) {
    std::string id = base;
    for (int k = 2; !ids_.insert(id).second; ++k) id = base + "_" + std::to_string(k);
    return id;
  }

  // One parameter over components [first, first + count) of uniform `index`. `part` names the
  // component(s) for a uniform split in two ('a' for a colour's alpha), 0 for a whole uniform.
  void add(const UniformInfo& u, int index, int first, int count, pfx_param_type type, char part,
           const std::vector<std::string>& labels = {}) {
    const auto& a = u.annotations;
    pfx_param_desc d{};
    d.struct_size = sizeof(pfx_param_desc);
    std::string name = u.name.substr(u.name.rfind(':') == std::string::npos ? 0 : u.name.rfind(':') + 1);
    std::string suffix = part == 0 || part == 'r' ? "" : part == 'a' ? "_alpha" : std::string("_") + part;
    d.id = t_.keep(unique_id(identifier_from(name) + suffix));
    std::string label = annotation_string(a, "ui_label", name);
    d.label = t_.keep(part == 'a' ? label + " (alpha)" : part == 'w' ? label + " (w)" : part && part != 'r' ? label + " (" + part + ")" : label);
    // A UI shows a tooltip for every parameter; an effect without one still says what it sets.
    d.tooltip = t_.keep(annotation_string(a, "ui_tooltip", "The effect's uniform " + u.name + " (" + pfx::fx::type_name(u.type) + ")."));
    d.unit = t_.keep(annotation_string(a, "ui_units"));
    d.group = t_.keep(annotation_string(a, "ui_category"));
    d.type = type;
    bool whole = u.type.base == BaseType::kInt || u.type.base == BaseType::kUint;
    for (int c = 0; c < count && c < 4; ++c) d.default_value.v[c] = u.initial[static_cast<std::size_t>(first + c)];
    if (type == PFX_PARAM_BOOL) {
      d.hard_min = 0, d.hard_max = 1, d.display_min = 0, d.display_max = 1, d.step = 1;
      d.default_value.v[0] = d.default_value.v[0] != 0 ? 1 : 0;
    } else if (type == PFX_PARAM_ENUM) {
      std::vector<pfx_enum_item> items;
      std::set<std::string> item_ids;
      for (std::size_t i = 0; i < labels.size(); ++i) {
        std::string id = identifier_from(labels[i]);
        for (int k = 2; !item_ids.insert(id).second; ++k) id = identifier_from(labels[i]) + "_" + std::to_string(k);
        items.push_back({t_.keep(id), t_.keep(labels[i])});
      }
      t_.items.push_back(std::move(items));
      d.items = t_.items.back().data();
      d.item_count = static_cast<uint32_t>(labels.size());
      d.hard_min = 0, d.hard_max = labels.size() - 1.0, d.display_min = 0, d.display_max = d.hard_max, d.step = 1;
      d.default_value.v[0] = std::min(std::max(d.default_value.v[0], 0.0), d.hard_max);
    } else {
      // ReShade lets a user type any value past a slider's ends, so the hard range is the float's;
      // the ui range is the display range.
      d.hard_min = whole ? -2147483648.0 : -static_cast<double>(FLT_MAX);
      d.hard_max = whole ? (u.type.base == BaseType::kUint ? 4294967295.0 : 2147483647.0) : static_cast<double>(FLT_MAX);
      if (u.type.base == BaseType::kUint) d.hard_min = 0;
      double low = annotation_min(a, "ui_min", std::min(0.0, d.default_value.v[0]));
      double high = annotation_max(a, "ui_max", std::max(whole ? 100.0 : 1.0, d.default_value.v[0]));
      if (type == PFX_PARAM_COLOR && !pfx::fx::has_annotation(a, "ui_min")) low = 0, high = 1;
      if (!(high > low)) high = low + 1;
      d.display_min = std::max(low, d.hard_min);
      d.display_max = std::min(high, d.hard_max);
      d.step = annotation_number(a, "ui_step", whole ? 1.0 : 0.0);
      for (int c = 0; c < count; ++c) d.default_value.v[c] = std::min(std::max(d.default_value.v[c], d.hard_min), d.hard_max);
    }
    t_.descs.push_back(d);
    t_.bindings.push_back({u.name, index, first, count, whole});
    t_.fx_names.push_back(part == 'a' || part == 'w' ? u.name + ".w" : u.name);
  }

  const pfx::fx::EffectModel& model_;
  ParamTable& t_;
  std::set<std::string> ids_;
};

}  // namespace

void build_params(const pfx::fx::EffectModel& model, ParamTable& table, std::vector<std::string>& warnings) {
  // Reserve so the items' data pointers never move while descriptors point at them.
  table.items.reserve(model.uniforms.size());
  Builder builder(model, table);
  for (std::size_t i = 0; i < model.uniforms.size(); ++i) builder.uniform(static_cast<int>(i), warnings);
}

}  // namespace pfx_fx
