#pragma once
// GLSL identifiers for an effect's global variables, structs and functions, made from the
// model's qualified FX names in declaration order: a prefix naming the kind (glsl_identifiers),
// and a number after a name already taken ("G_x_2"). Overloads and prototypes of a function share
// one identifier: GLSL tells overloads apart by their parameter types too.
#include <map>
#include <set>
#include <string>

#include "../model/effect_model.hpp"

namespace pfx::fx {

class GlslNames {
 public:
  explicit GlslNames(const EffectModel& model);

  // The identifier of a global variable, struct or function; null for one the model does not
  // declare (a local).
  const std::string* of(const VariableDecl* variable) const { return find(variables_, variable); }
  const std::string* of(const StructDecl* structure) const { return find(structs_, structure); }
  const std::string* of(const FunctionDecl* function) const { return find(functions_, function); }
  // The identifier of a global variable the model declares.
  const std::string& global(const VariableDecl* variable) const { return variables_.at(variable); }

 private:
  template <typename Key>
  static const std::string* find(const std::map<const Key*, std::string>& names, const Key* key) {
    auto it = names.find(key);
    return it == names.end() ? nullptr : &it->second;
  }
  std::string unique(const std::string& name);

  std::map<const VariableDecl*, std::string> variables_;
  std::map<const StructDecl*, std::string> structs_;
  std::map<const FunctionDecl*, std::string> functions_;
  std::set<std::string> used_;
};

}  // namespace pfx::fx
