#include "glsl_names.hpp"

#include "glsl_identifiers.hpp"

namespace pfx::fx {

GlslNames::GlslNames(const EffectModel& model) {
  std::map<std::string, std::string> by_function;  // qualified name -> identifier
  for (const EffectModel::Declared& d : model.declared) {
    if (d.variable) {
      variables_[d.variable] = unique(glsl_safe("G_" + d.qualified));
    } else if (d.structure) {
      structs_[d.structure] = unique(glsl_safe("S_" + d.qualified));
    } else if (d.function) {
      auto it = by_function.find(d.qualified);
      if (it == by_function.end()) it = by_function.emplace(d.qualified, unique(glsl_safe("F_" + d.qualified))).first;
      functions_[d.function] = it->second;
    }
  }
}

std::string GlslNames::unique(const std::string& name) {
  std::string candidate = name;
  for (int n = 2; !used_.insert(candidate).second; ++n) candidate = name + "_" + std::to_string(n);
  return candidate;
}

}  // namespace pfx::fx
