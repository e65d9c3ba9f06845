#include "frei0r_tables.hpp"

#include <cstdio>

#include <pfx/host/param_store.hpp>

#include "frei0r_api.hpp"
#include "frei0r_params.hpp"

namespace pfx::frei0r {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

const char* type_name(int type) {
  switch (type) {
    case F0R_PARAM_BOOL: return "bool";
    case F0R_PARAM_DOUBLE: return "double";
    case F0R_PARAM_COLOR: return "color";
    case F0R_PARAM_POSITION: return "position";
    default: return "string";
  }
}

std::string meaning(const pfx_param_desc& desc) {
  switch (desc.type) {
    case PFX_PARAM_FLOAT:
    case PFX_PARAM_INT:
    case PFX_PARAM_VEC2: return unit_mapping_text(desc) + (desc.type == PFX_PARAM_INT ? ", whole numbers" : "");
    case PFX_PARAM_BOOL: return "on or off";
    case PFX_PARAM_COLOR: return "linear RGB";
    case PFX_PARAM_VEC3: return "x,y,z";
    default: {
      std::string items;
      for (uint32_t i = 0; i < desc.item_count; ++i) items += std::string(i ? ", " : "") + "`" + desc.items[i].id + "`";
      return items;
    }
  }
}

// The default as the frei0r host shows it.
std::string frei0r_default(const pfx_param_desc& desc, const pfx_value& value, const std::string& text) {
  switch (desc.type) {
    case PFX_PARAM_FLOAT:
    case PFX_PARAM_INT: return number(to_unit(desc, value.v[0]));
    case PFX_PARAM_VEC2: return number(to_unit(desc, value.v[0])) + ", " + number(to_unit(desc, value.v[1]));
    case PFX_PARAM_BOOL: return value.v[0] != 0 ? "1" : "0";
    default: return text;
  }
}

}  // namespace

std::string markdown_table(const pfx_effect_desc& effect) {
  host::ParamStore display(host::DefaultSet::DISPLAY_REFERRED), scene;
  display.add_effect(&effect);
  scene.add_effect(&effect);
  const std::string id = effect.id;
  std::string dashed = id;
  for (char& c : dashed)
    if (c == '_') c = '-';
  std::string table = "#### pfx_" + id + "\n\n" + (effect.label ? effect.label : id) +
                      ": ffmpeg `frei0r=filter_name=pfx_" + id + "`, MLT `frei0r.pfx_" + id +
                      "`, GStreamer `frei0r-filter-pfx-" + dashed + "`.\n\n" +
                      "| # | parameter | frei0r type | value | default (frei0r) | default (pfx) | scene-referred default |\n"
                      "|---|---|---|---|---|---|---|\n";
  const pfx_value* values = display.values(id);
  for (uint32_t i = 0; i < effect.param_count; ++i) {
    const pfx_param_desc& desc = effect.params[i];
    const std::string key = id + "." + desc.id;
    const std::string shown = display.get_text(key), scene_text = scene.get_text(key);
    table += "| " + std::to_string(i) + " | `" + desc.id + "` | " + type_name(frei0r_type(desc)) + " | " + meaning(desc) +
             " | " + frei0r_default(desc, values[i], shown) + " | " + shown + " | " +
             (scene_text == shown ? "" : "**" + scene_text + "**") + " |\n";
  }
  return table;
}

}  // namespace pfx::frei0r
