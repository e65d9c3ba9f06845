#include "descriptor_check.hpp"

#include <cmath>
#include <set>

namespace pfx::host {

int param_component_count(pfx_param_type type) {
  switch (type) {
    case PFX_PARAM_VEC2: return 2;
    case PFX_PARAM_COLOR:
    case PFX_PARAM_VEC3: return 3;
    default: return 1;
  }
}

bool is_identifier(const char* text) {
  if (!text || !*text) return false;
  for (const char* c = text; *c; ++c)
    if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_')) return false;
  return true;
}

std::string check_param_descriptor(const pfx_param_desc& param) {
  if (param.struct_size < PFX_PARAM_DESC_MIN_SIZE) return "descriptor struct too small";
  if (!is_identifier(param.id)) return "id must be non-empty [a-z0-9_]+";
  const std::string name = std::string("parameter '") + param.id + "': ";
  if (param.type > PFX_PARAM_VEC3) return name + "unknown type " + std::to_string(param.type);
  if (std::isnan(param.hard_min) || std::isnan(param.hard_max) || param.hard_min > param.hard_max)
    return name + "hard range is empty or NaN";
  const bool display_default = (param.flags & PFX_PARAM_HAS_DISPLAY_DEFAULT) &&
                               PFX_STRUCT_HAS(&param, pfx_param_desc, display_default);
  for (int i = 0; i < param_component_count(param.type); ++i) {
    double value = param.default_value.v[i];
    if (std::isnan(value) || value < param.hard_min || value > param.hard_max)
      return name + "default outside the hard range";
    value = param.display_default.v[i];
    if (display_default && (std::isnan(value) || value < param.hard_min || value > param.hard_max))
      return name + "display-referred default outside the hard range";
  }
  if (param.type == PFX_PARAM_ENUM) {
    if (!param.items || param.item_count == 0) return name + "enum without items";
    if (param.hard_min != 0 || param.hard_max != param.item_count - 1.0)
      return name + "enum hard range must be [0, item_count - 1]";
    std::set<std::string> ids;
    for (uint32_t i = 0; i < param.item_count; ++i) {
      if (!is_identifier(param.items[i].id)) return name + "enum item id must be [a-z0-9_]+";
      if (!ids.insert(param.items[i].id).second) return name + "duplicate enum item '" + param.items[i].id + "'";
    }
  }
  if ((param.type == PFX_PARAM_INT || param.type == PFX_PARAM_ENUM || param.type == PFX_PARAM_BOOL) &&
      (param.default_value.v[0] != std::floor(param.default_value.v[0]) ||
       (display_default && param.display_default.v[0] != std::floor(param.display_default.v[0]))))
    return name + "default of a whole-number parameter is not whole";
  return "";
}

std::string check_effect_descriptor(const pfx_effect_desc* desc) {
  if (!desc) return "NULL descriptor";
  if (desc->struct_size < PFX_EFFECT_DESC_MIN_SIZE) return "descriptor struct too small";
  if (!is_identifier(desc->id)) return "effect id must be non-empty [a-z0-9_]+";
  const std::string name = std::string("effect '") + desc->id + "': ";
  if (!desc->create || !desc->destroy || !desc->declare || !desc->run_pass)
    return name + "create, destroy, declare and run_pass are required";
  if (desc->param_count && !desc->params) return name + "param_count without params";
  std::set<std::string> ids;
  for (uint32_t i = 0; i < desc->param_count; ++i) {
    std::string problem = check_param_descriptor(desc->params[i]);
    if (!problem.empty()) return name + problem;
    if (!ids.insert(desc->params[i].id).second) return name + "duplicate parameter id '" + desc->params[i].id + "'";
  }
  return "";
}

std::string check_importer_descriptor(const pfx_importer_desc* desc) {
  if (!desc) return "NULL importer descriptor";
  if (desc->struct_size < PFX_IMPORTER_DESC_MIN_SIZE) return "importer descriptor struct too small";
  if (!is_identifier(desc->id)) return "importer id must be non-empty [a-z0-9_]+";
  const std::string name = std::string("importer '") + desc->id + "': ";
  if (!desc->import || !desc->release) return name + "import and release are required";
  if (desc->extension_count == 0 || !desc->extensions) return name + "declares no file extension";
  for (uint32_t i = 0; i < desc->extension_count; ++i) {
    const char* ext = desc->extensions[i];
    if (!ext || !*ext || *ext == '.') return name + "extension #" + std::to_string(i) + " is empty or starts with '.'";
    for (const char* c = ext; *c; ++c)
      if (*c >= 'A' && *c <= 'Z') return name + "extension '" + ext + "' must be lower case";
  }
  return "";
}

}  // namespace pfx::host
