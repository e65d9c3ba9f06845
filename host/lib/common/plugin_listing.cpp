#include "plugin_listing.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace pfx::app {
namespace {

const char* type_name(pfx_param_type type) {
  switch (type) {
    case PFX_PARAM_FLOAT: return "float";
    case PFX_PARAM_INT: return "int";
    case PFX_PARAM_BOOL: return "bool";
    case PFX_PARAM_ENUM: return "enum";
    case PFX_PARAM_COLOR: return "color";
    case PFX_PARAM_VEC2: return "vec2";
    case PFX_PARAM_VEC3: return "vec3";
    default: return "unknown";
  }
}

// JSON has no infinity: unbounded ranges are written as null.
nlohmann::ordered_json number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

// The slider's range, and what a value may be beyond it: "[0, 4] (accepts [0, 65504])" where the
// hard range is wider and bounded, "[0, 1] (accepts any value)" where it is the type's own (an FX
// uniform's: ReShade lets a value go past a slider's ends), "[0, 16]" where the two are one.
std::string range_text(const pfx_param_desc& p) {
  char text[160];
  std::snprintf(text, sizeof text, "[%g, %g]", p.display_min, p.display_max);
  std::string range = text;
  if (p.hard_min == p.display_min && p.hard_max == p.display_max) return range;
  const double unbounded = 1e30;  // beyond any slider: the float's and the int's own limits
  if (!(std::fabs(p.hard_min) < unbounded && std::fabs(p.hard_max) < unbounded) ||
      (p.type == PFX_PARAM_INT && p.hard_min <= -2147483648.0 && p.hard_max >= 2147483647.0))
    return range + " (accepts any value)";
  std::snprintf(text, sizeof text, " (accepts [%g, %g])", p.hard_min, p.hard_max);
  return range + text;
}

}  // namespace

int component_count(pfx_param_type type) {
  return type == PFX_PARAM_VEC2 ? 2 : (type == PFX_PARAM_COLOR || type == PFX_PARAM_VEC3) ? 3 : 1;
}

std::string value_text(const pfx_param_desc& p, const pfx_value& value) {
  if (p.type == PFX_PARAM_ENUM) {
    auto index = static_cast<uint32_t>(value.v[0]);
    return index < p.item_count ? p.items[index].id : "?";
  }
  if (p.type == PFX_PARAM_BOOL) return value.v[0] != 0 ? "true" : "false";
  std::string text;
  for (int i = 0; i < component_count(p.type); ++i) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value.v[i]);
    text += (i ? "," : "") + std::string(buffer);
  }
  return text;
}

std::string default_value_text(const pfx_param_desc& p) { return value_text(p, p.default_value); }

bool has_display_default(const pfx_param_desc& p) {
  return (p.flags & PFX_PARAM_HAS_DISPLAY_DEFAULT) && PFX_STRUCT_HAS(&p, pfx_param_desc, display_default);
}

nlohmann::ordered_json value_json(const pfx_param_desc& p, const pfx_value& value) {
  if (p.type == PFX_PARAM_ENUM) return value_text(p, value);
  if (p.type == PFX_PARAM_BOOL) return value.v[0] != 0;
  if (component_count(p.type) == 1) return number(value.v[0]);
  auto array = nlohmann::ordered_json::array();
  for (int c = 0; c < component_count(p.type); ++c) array.push_back(number(value.v[c]));
  return array;
}

nlohmann::ordered_json parameter_json(const pfx_effect_desc& effect, const pfx_param_desc& d) {
  nlohmann::ordered_json q;
  q["id"] = d.id;
  q["key"] = std::string(effect.id) + "." + d.id;
  q["label"] = d.label ? d.label : d.id;
  q["tooltip"] = d.tooltip ? d.tooltip : "";
  q["unit"] = d.unit ? d.unit : "";
  q["group"] = d.group ? d.group : "";
  q["type"] = type_name(d.type);
  q["hard_min"] = number(d.hard_min);
  q["hard_max"] = number(d.hard_max);
  q["display_min"] = number(d.display_min);
  q["display_max"] = number(d.display_max);
  q["step"] = number(d.step);
  q["out_of_range"] = (d.flags & PFX_PARAM_REJECT_OUT_OF_RANGE) ? "reject" : "clamp";
  q["logarithmic"] = (d.flags & PFX_PARAM_LOGARITHMIC) != 0;
  q["default"] = value_json(d, d.default_value);
  if (has_display_default(d)) q["display_default"] = value_json(d, d.display_default);
  // Default and display range above are a 1920x1080 frame's; an instance runs with its frame's.
  if (d.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) q["follows_frame_size"] = true;
  if (d.type == PFX_PARAM_ENUM) {
    q["items"] = nlohmann::ordered_json::array();
    for (uint32_t k = 0; k < d.item_count; ++k)
      q["items"].push_back({{"id", d.items[k].id}, {"label", d.items[k].label ? d.items[k].label : d.items[k].id}});
  }
  return q;
}

nlohmann::ordered_json effect_json(const pfx_effect_desc& effect) {
  nlohmann::ordered_json e;
  e["id"] = effect.id;
  e["label"] = effect.label ? effect.label : effect.id;
  e["description"] = effect.description ? effect.description : "";
  e["parameters"] = nlohmann::ordered_json::array();
  for (uint32_t i = 0; i < effect.param_count; ++i) e["parameters"].push_back(parameter_json(effect, effect.params[i]));
  return e;
}

std::string plugin_listing_text(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& load_errors) {
  std::string out;
  char line[512];
  for (const auto& plugin : registry.plugins()) {
    out += plugin->id + " " + plugin->version + " (" + plugin->name + ")  " + plugin->path + "\n";
    for (const pfx_effect_desc* effect : plugin->effects) {
      out += "  effect " + std::string(effect->id) + ": " + (effect->description ? effect->description : "") + "\n";
      for (uint32_t i = 0; i < effect->param_count; ++i) {
        const pfx_param_desc& p = effect->params[i];
        std::snprintf(line, sizeof line, "    %s.%-18s %-6s default %-10s range %s %s\n", effect->id, p.id,
                      type_name(p.type), default_value_text(p).c_str(), range_text(p).c_str(), p.unit ? p.unit : "");
        out += line;
        if (has_display_default(p))
          out += "      default on display-referred (8-bit) frames: " + value_text(p, p.display_default) + "\n";
        if (p.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) {
          std::snprintf(line, sizeof line, "      default and slider range [%g, %g] depend on the frame size (shown for 1920x1080)\n",
                        p.display_min, p.display_max);
          out += line;
        }
        if (p.type == PFX_PARAM_ENUM) {
          out += "      one of:";
          for (uint32_t k = 0; k < p.item_count; ++k) out += std::string(" ") + p.items[k].id;
          out += "\n";
        }
      }
    }
  }
  if (registry.plugins().empty()) out += "no plugins loaded\n";
  for (const auto& error : load_errors) out += "not loaded: " + error + "\n";
  return out;
}

std::string plugin_listing_json(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& load_errors) {
  nlohmann::ordered_json root;
  root["plugins"] = nlohmann::ordered_json::array();
  for (const auto& plugin : registry.plugins()) {
    nlohmann::ordered_json p;
    p["id"] = plugin->id;
    p["name"] = plugin->name;
    p["version"] = plugin->version;
    p["path"] = plugin->path;
    p["abi"] = std::to_string(PFX_ABI_MAJOR) + "." + std::to_string(plugin->abi_minor);
    p["effects"] = nlohmann::ordered_json::array();
    for (const pfx_effect_desc* effect : plugin->effects) {
      nlohmann::ordered_json e = effect_json(*effect);
      // An effect made from a file: a ReShade FX file's technique (the FX plugin), a libretro preset
      // (the libretro plugin), or a file of another plugin.
      auto source = plugin->effect_sources.find(effect->id);
      if (source != plugin->effect_sources.end()) {
        const bool fx = plugin->id == "org.pfx.fx", libretro = plugin->id == "org.pfx.libretro";
        e[fx ? "fx_file" : libretro ? "libretro_preset" : "source_file"] = source->second.file;
        if (!libretro) e[fx ? "fx_technique" : "source_name"] = source->second.name;
      }
      p["effects"].push_back(e);
    }
    root["plugins"].push_back(p);
  }
  root["load_errors"] = load_errors;
  return root.dump(2);
}

}  // namespace pfx::app
