#include "descriptor_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <cstdio>
#include <cstdlib>

namespace pfx::validate {
namespace {

bool present(const char* text) { return text && *text; }

int component_count(pfx_param_type type) {
  switch (type) {
    case PFX_PARAM_VEC2: return 2;
    case PFX_PARAM_VEC3:
    case PFX_PARAM_COLOR: return 3;
    default: return 1;
  }
}

bool whole_type(pfx_param_type type) {
  return type == PFX_PARAM_INT || type == PFX_PARAM_BOOL || type == PFX_PARAM_ENUM;
}

std::string number(double v) {
  char buffer[32];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15) {
    std::snprintf(buffer, sizeof buffer, "%.0f", v);
    return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  // Shortest form that reads back the same keeps messages readable ("5", not "5.0000000000000000").
  for (int precision = 1; precision < 17; ++precision) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", precision, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buffer;
}

}  // namespace

bool is_plugin_id(const char* id) {
  if (!present(id)) return false;
  int parts = 1;
  size_t part_length = 0;
  for (const char* c = id; *c; ++c) {
    if (*c == '.') {
      if (part_length == 0) return false;
      ++parts;
      part_length = 0;
    } else if ((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_' || *c == '-') {
      ++part_length;
    } else {
      return false;
    }
  }
  return parts >= 2 && part_length > 0;
}

bool is_effect_or_param_id(const char* id) {
  if (!present(id)) return false;
  for (const char* c = id; *c; ++c)
    if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_')) return false;
  return true;
}

std::vector<std::string> param_descriptor_problems(const pfx_param_desc& p) {
  std::vector<std::string> problems;
  const std::string name = "parameter '" + std::string(p.id ? p.id : "(null)") + "': ";
  auto problem = [&](const std::string& text) { problems.push_back(name + text); };

  if (p.struct_size < PFX_PARAM_DESC_MIN_SIZE)
    problem("struct_size " + std::to_string(p.struct_size) + " is smaller than pfx_param_desc's first version (" +
            std::to_string(PFX_PARAM_DESC_MIN_SIZE) + ")");
  if (!is_effect_or_param_id(p.id)) problem("the id is not [a-z0-9_]+");
  if (!present(p.label)) problem("no label");
  if (!present(p.tooltip)) problem("no tooltip");
  if (!p.unit) problem("unit is NULL (use \"\" for none)");
  if (!p.group) problem("group is NULL (use \"\" for none)");
  if (p.type > PFX_PARAM_VEC3) {
    problem("unknown type " + std::to_string(p.type));
    return problems;
  }
  if (std::isnan(p.hard_min) || std::isnan(p.hard_max) || std::isnan(p.display_min) || std::isnan(p.display_max))
    problem("a range bound is NaN");
  if (!(p.hard_min <= p.hard_max))
    problem("hard range [" + number(p.hard_min) + ", " + number(p.hard_max) + "] is empty");
  if (!(p.display_min <= p.display_max))
    problem("display range [" + number(p.display_min) + ", " + number(p.display_max) + "] is empty");
  if (p.display_min < p.hard_min || p.display_max > p.hard_max)
    problem("display range [" + number(p.display_min) + ", " + number(p.display_max) + "] is not inside the hard range [" +
            number(p.hard_min) + ", " + number(p.hard_max) + "]");
  if (!std::isfinite(p.display_min) || !std::isfinite(p.display_max))
    problem("display range is not finite (a slider needs finite ends)");
  if (!(p.step >= 0) || !std::isfinite(p.step)) problem("step " + number(p.step) + " is not a finite number >= 0");
  if ((p.flags & PFX_PARAM_LOGARITHMIC) && !(p.display_min > 0))
    problem("logarithmic, but the display range does not start above 0");
  if (p.flags & ~uint32_t(PFX_PARAM_REJECT_OUT_OF_RANGE | PFX_PARAM_LOGARITHMIC | PFX_PARAM_HAS_DISPLAY_DEFAULT |
                           PFX_PARAM_FOLLOWS_FRAME_SIZE))
    problem("unknown flag bits " + std::to_string(p.flags));

  const int n = component_count(p.type);
  const auto check_default = [&](const pfx_value& value, const std::string& name) {
    for (int i = 0; i < 4; ++i) {
      const double v = value.v[i];
      const std::string which = n > 1 ? name + " component " + std::to_string(i) : name;
      if (i >= n) {
        if (v != 0) problem(which + " is " + number(v) + " but the type uses " + std::to_string(n) + " (unused ones must be 0)");
        continue;
      }
      if (std::isnan(v)) problem(which + " is NaN");
      else if (v < p.hard_min) problem(which + " " + number(v) + " is below hard_min " + number(p.hard_min));
      else if (v > p.hard_max) problem(which + " " + number(v) + " is above hard_max " + number(p.hard_max));
      if (whole_type(p.type) && std::isfinite(v) && v != std::floor(v)) problem(which + " " + number(v) + " is not a whole number");
    }
  };
  check_default(p.default_value, "default");
  if ((p.flags & PFX_PARAM_HAS_DISPLAY_DEFAULT) && PFX_STRUCT_HAS(&p, pfx_param_desc, display_default))
    check_default(p.display_default, "display-referred default");
  if (p.type == PFX_PARAM_BOOL && (p.hard_min != 0 || p.hard_max != 1)) problem("a bool's hard range must be [0, 1]");
  if (p.type == PFX_PARAM_INT && p.step != 0 && p.step != std::floor(p.step)) problem("an int's step must be whole");

  if (p.type == PFX_PARAM_ENUM) {
    if (p.item_count == 0 || !p.items) {
      problem("an enum with no items");
    } else {
      if (p.hard_min != 0 || p.hard_max != double(p.item_count - 1))
        problem("an enum's hard range must be [0, " + std::to_string(p.item_count - 1) + "]");
      std::set<std::string> ids;
      for (uint32_t i = 0; i < p.item_count; ++i) {
        const pfx_enum_item& item = p.items[i];
        const std::string label = "item " + std::to_string(i);
        if (!is_effect_or_param_id(item.id)) problem(label + ": the id is not [a-z0-9_]+");
        else if (!ids.insert(item.id).second) problem(label + ": id '" + item.id + "' repeats");
        if (!present(item.label)) problem(label + ": no label");
      }
    }
  } else if (p.items || p.item_count) {
    problem("items given, but the type is not enum");
  }
  return problems;
}

std::vector<std::string> effect_descriptor_problems(const pfx_effect_desc& e) {
  std::vector<std::string> problems;
  if (e.struct_size < PFX_EFFECT_DESC_MIN_SIZE)
    problems.push_back("struct_size " + std::to_string(e.struct_size) + " is smaller than pfx_effect_desc's first version (" +
                       std::to_string(PFX_EFFECT_DESC_MIN_SIZE) + ")");
  if (!is_effect_or_param_id(e.id)) problems.push_back("the effect id is not [a-z0-9_]+");
  if (!present(e.label)) problems.push_back("no label");
  if (!present(e.description)) problems.push_back("no description");
  if (!e.create || !e.destroy || !e.declare || !e.run_pass)
    problems.push_back("create, destroy, declare and run_pass are all required");
  if (e.param_count > 0 && !e.params) problems.push_back("param_count is " + std::to_string(e.param_count) + " but params is NULL");
  if (e.params && e.param_count > 0 && e.params[0].struct_size < PFX_PARAM_DESC_MIN_SIZE) {
    // The array's stride is its first element's struct_size: too small, nothing after it can be found.
    problems.push_back("parameter #0: struct_size " + std::to_string(e.params[0].struct_size) +
                       " is smaller than pfx_param_desc's first version (" + std::to_string(PFX_PARAM_DESC_MIN_SIZE) + ")");
    return problems;
  }
  std::set<std::string> ids;
  for (uint32_t i = 0; e.params && i < e.param_count; ++i) {
    // Stepped by the plugin's struct_size and read as far as it reaches (core.h's growth rule), so
    // a plugin of another minor version is checked for what it is.
    const pfx_param_desc* element = pfx_at(pfx_param_desc, e.params, i);
    if (element->struct_size != e.params[0].struct_size) {
      problems.push_back("parameter #" + std::to_string(i) + ": struct_size " + std::to_string(element->struct_size) +
                         " differs from parameter #0's " + std::to_string(e.params[0].struct_size) +
                         " (the elements of one array share one size)");
      break;
    }
    pfx_param_desc p{};
    std::memcpy(&p, element, std::min<size_t>(element->struct_size, sizeof p));
    for (std::string& problem : param_descriptor_problems(p)) problems.push_back(std::move(problem));
    if (p.id && !ids.insert(p.id).second) problems.push_back("parameter '" + std::string(p.id) + "': the id repeats");
  }
  return problems;
}

}  // namespace pfx::validate
