// Functions (overloads, prototypes and definitions) and techniques.
#include "analyzer.hpp"

namespace pfx::fx {
namespace {

bool same_parameters(const FunctionDecl& a, const FunctionDecl& b) {
  if (a.parameters.size() != b.parameters.size()) return false;
  for (std::size_t i = 0; i < a.parameters.size(); ++i)
    if (a.parameters[i].resolved != b.parameters[i].resolved) return false;
  return true;
}


}  // namespace

void Analyzer::declare_function(FunctionDecl& function) {
  function.resolved = resolve_type(function.return_type, function.location);
  for (VariableDecl& p : function.parameters) {
    Type type = resolve_type(p.type, p.location);
    if (!is_error(type) && !resolve_array_sizes(p, type)) type = error_type();
    p.resolved = type;
  }
  // A variable of the same name may stand beside it, as ReShade allows (`static const float3x3
  // RGBtoYIQ` and `float3 RGBtoYIQ(float3 c)`): a call looks for functions, a value for variables.
  std::string qualified = namespace_prefix_ + function.name;
  std::vector<FunctionDecl*>& overloads = functions_[qualified];
  bool replaced = false;
  for (FunctionDecl*& existing : overloads) {
    if (!same_parameters(*existing, function)) continue;
    if (existing->body && function.body) {
      diagnostics_.error(function.location, "redefinition of function '" + function.name + "'");
    } else if (function.body) {
      definition_of_[existing] = &function;
      existing = &function;
    }
    replaced = true;
  }
  if (!replaced) overloads.push_back(&function);
  if (!function.body) return;
  current_function_ = &function;
  push_scope();
  for (VariableDecl& p : function.parameters) {
    if (p.initializer) {
      check(*p.initializer);
      convert(p.initializer, p.resolved, "the default of parameter '" + p.name + "'");
    }
    if (scopes_.back().count(p.name)) diagnostics_.error(p.location, "duplicate parameter '" + p.name + "'");
    scopes_.back()[p.name] = &p;
  }
  check_statement(*function.body);
  pop_scope();
  current_function_ = nullptr;
}

void Analyzer::check_technique(TechniqueDecl& technique) {
  for (Annotation& a : technique.annotations) check(*a.value);
  for (PassDecl& pass : technique.passes) check_states(pass.states, StateOwner::kPass);
}


}  // namespace pfx::fx
