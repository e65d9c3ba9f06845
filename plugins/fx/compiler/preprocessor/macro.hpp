#pragma once
// A macro definition and the table of those in force.
#include <map>
#include <string>
#include <vector>

#include "../token.hpp"

namespace pfx::fx {

enum class BuiltinMacro { kNone, kFile, kFileName, kFileStem, kLine };

struct Macro {
  std::string name;
  std::uint32_t id = 0;  // stable while defined: what hide sets hold
  bool function_like = false;
  bool variadic = false;  // the last parameter is "..." (named __VA_ARGS__ in the body)
  std::vector<std::string> parameters;
  TokenList body;
  SourceLocation location;
  BuiltinMacro builtin = BuiltinMacro::kNone;

  int parameter_index(const std::string& identifier) const {
    for (std::size_t i = 0; i < parameters.size(); ++i)
      if (parameters[i] == identifier) return static_cast<int>(i);
    return -1;
  }
};

class MacroTable {
 public:
  // Replaces any earlier definition; returns the stored macro.
  const Macro& define(Macro macro) {
    macro.id = next_id_++;
    return macros_[macro.name] = std::move(macro);
  }
  bool undefine(const std::string& name) { return macros_.erase(name) > 0; }
  const Macro* find(const std::string& name) const {
    auto it = macros_.find(name);
    return it == macros_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, Macro> macros_;
  std::uint32_t next_id_ = 1;
};

}  // namespace pfx::fx
