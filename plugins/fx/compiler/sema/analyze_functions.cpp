// Functions (overloads, prototypes and definitions), techniques and the states of passes and
// texture/sampler/storage blocks.
#include "analyzer.hpp"
#include "constant_eval.hpp"

namespace pfx::fx {
namespace {

bool same_parameters(const FunctionDecl& a, const FunctionDecl& b) {
  if (a.parameters.size() != b.parameters.size()) return false;
  for (std::size_t i = 0; i < a.parameters.size(); ++i)
    if (a.parameters[i].resolved != b.parameters[i].resolved) return false;
  return true;
}

bool is_render_target_state(const std::string& name) {
  return name == "RenderTarget" || (name.size() == 13 && name.compare(0, 12, "RenderTarget") == 0 && name[12] >= '0' && name[12] <= '7');
}

}  // namespace

void Analyzer::declare_function(FunctionDecl& function) {
  function.resolved = resolve_type(function.return_type, function.location);
  for (VariableDecl& p : function.parameters) {
    Type type = resolve_type(p.type, p.location);
    if (!is_error(type) && !resolve_array_sizes(p, type)) type = error_type();
    p.resolved = type;
  }
  std::string qualified = namespace_prefix_ + function.name;
  if (globals_.count(qualified)) diagnostics_.error(function.location, "redefinition of '" + function.name + "'");
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
  for (PassDecl& pass : technique.passes) check_states(pass.states);
}

void Analyzer::check_states(std::vector<StateAssignment>& states) {
  for (StateAssignment& state : states) {
    Expr& value = *state.value;
    bool shader = state.name == "VertexShader" || state.name == "PixelShader" || state.name == "ComputeShader";
    if (shader) {
      const auto* overloads = find_functions(value.text);
      if (!overloads) diagnostics_.error(value.location, "unknown function '" + value.text + "' in " + state.name);
      else value.function = overloads->front();
      for (ExprPtr& size : state.thread_group) {
        check(*size);
        auto n = evaluate_integer_constant(*size);
        if (!n || *n < 1 || *n > 1024) diagnostics_.error(size->location, "thread group size must be a constant from 1 to 1024");
      }
      continue;
    }
    bool names_texture = state.name == "Texture" || is_render_target_state(state.name);
    if (value.kind == ExprKind::kName) {
      // A state value may be an enumerant (CLAMP, LINEAR, SRCALPHA) rather than a variable.
      value.variable = find_variable(value.text);
      if (value.variable) value.resolved = value.variable->resolved;
      if (names_texture && (!value.variable || value.variable->resolved.base != BaseType::kTexture))
        diagnostics_.error(value.location, "'" + state.name + "' must name a texture, not '" + value.text + "'");
      continue;
    }
    if (names_texture) {
      diagnostics_.error(value.location, "'" + state.name + "' must name a texture");
      continue;
    }
    check(value);
  }
}

}  // namespace pfx::fx
