#include "frei0r_params.hpp"

#include <cmath>
#include <cstdio>

#include "frei0r_api.hpp"

namespace pfx::frei0r {
namespace {

bool logarithmic(const pfx_param_desc& desc) {
  return (desc.flags & PFX_PARAM_LOGARITHMIC) && desc.display_min > 0 && desc.display_max > desc.display_min;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string explanation(const pfx_param_desc& desc) {
  std::string text = std::string(desc.label ? desc.label : desc.id) + ". " + (desc.tooltip ? desc.tooltip : "");
  switch (desc.type) {
    case PFX_PARAM_FLOAT:
    case PFX_PARAM_INT:
    case PFX_PARAM_VEC2: text += " (" + unit_mapping_text(desc) + ")"; break;
    case PFX_PARAM_ENUM: {
      text += " (one of:";
      for (uint32_t i = 0; i < desc.item_count; ++i) text += std::string(i ? ", " : " ") + desc.items[i].id;
      text += ")";
      break;
    }
    case PFX_PARAM_COLOR: text += " (linear RGB)"; break;
    case PFX_PARAM_VEC3: text += " (x,y,z)"; break;
    default: break;
  }
  return text;
}

}  // namespace

int frei0r_type(const pfx_param_desc& desc) {
  switch (desc.type) {
    case PFX_PARAM_BOOL: return F0R_PARAM_BOOL;
    case PFX_PARAM_COLOR: return F0R_PARAM_COLOR;
    case PFX_PARAM_VEC2: return F0R_PARAM_POSITION;
    case PFX_PARAM_ENUM:
    case PFX_PARAM_VEC3: return F0R_PARAM_STRING;
    default: return F0R_PARAM_DOUBLE;
  }
}

std::vector<ParamSlot> effect_slots(const pfx_effect_desc& effect) {
  std::vector<ParamSlot> slots;
  for (uint32_t i = 0; i < effect.param_count; ++i)
    slots.push_back({effect.params[i].id, frei0r_type(effect.params[i]), explanation(effect.params[i])});
  return slots;
}

double to_unit(const pfx_param_desc& desc, double value) {
  if (!(desc.display_max > desc.display_min)) return 0;
  if (logarithmic(desc))
    return value > 0 ? std::log(value / desc.display_min) / std::log(desc.display_max / desc.display_min) : 0;
  return (value - desc.display_min) / (desc.display_max - desc.display_min);
}

double from_unit(const pfx_param_desc& desc, double unit) {
  double value = logarithmic(desc) ? desc.display_min * std::pow(desc.display_max / desc.display_min, unit)
                                   : desc.display_min + unit * (desc.display_max - desc.display_min);
  if (desc.type == PFX_PARAM_INT) value = std::round(value);
  return value;
}

std::string unit_mapping_text(const pfx_param_desc& desc) {
  std::string unit = desc.unit && *desc.unit ? std::string(" ") + desc.unit : "";
  return "0-1 is " + number_text(desc.display_min) + "-" + number_text(desc.display_max) + unit +
         (logarithmic(desc) ? ", logarithmic" : "");
}

}  // namespace pfx::frei0r
