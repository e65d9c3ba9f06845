#pragma once
// A macro definition and the table of those in force.
#include <map>
#include <memory>
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

// A definition is shared, not owned by the table: an expansion holds the macro it expands, so an
// #undef or #define met while it collects the arguments (a directive inside a macro's argument
// list, which C leaves undefined) changes the table but not the definition in use, as GCC does.
class MacroTable {
 public:
  // Replaces any earlier definition; returns the stored macro.
  const Macro& define(Macro macro) {
    macro.id = next_id_++;
    auto stored = std::make_shared<const Macro>(std::move(macro));
    const Macro& result = *stored;
    macros_[result.name] = std::move(stored);
    return result;
  }
  bool undefine(const std::string& name) { return macros_.erase(name) > 0; }
  // Valid until the name is next defined or undefined.
  const Macro* find(const std::string& name) const { return hold(name).get(); }
  // The definition, kept alive for as long as the caller holds it.
  std::shared_ptr<const Macro> hold(const std::string& name) const {
    auto it = macros_.find(name);
    return it == macros_.end() ? nullptr : it->second;
  }

 private:
  std::map<std::string, std::shared_ptr<const Macro>> macros_;
  std::uint32_t next_id_ = 1;
};

}  // namespace pfx::fx
