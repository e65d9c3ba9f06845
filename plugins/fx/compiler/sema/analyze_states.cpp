// State blocks of textures, samplers and storages, and the states of passes: each name must be
// one its owner has, each value of the kind that state takes.
#include "../limits.hpp"
#include "../text_lists.hpp"
#include "analyzer.hpp"
#include "constant_eval.hpp"

namespace pfx::fx {

void Analyzer::check_object(VariableDecl& object) {
  const Type& type = object.resolved;
  StateOwner owner = type.base == BaseType::kTexture   ? StateOwner::kTexture
                     : type.base == BaseType::kSampler ? StateOwner::kSampler
                                                       : StateOwner::kStorage;
  if (!type.is_object()) {
    if (object.has_state_block) diagnostics_.error(object.location, "only textures, samplers and storages have state blocks");
    return;
  }
  check_states(object.states, owner);
  if (owner == StateOwner::kTexture) return;
  bool has_texture = false;
  for (const StateAssignment& state : object.states) has_texture = has_texture || state.name == "Texture";
  if (!has_texture) diagnostics_.error(object.location, std::string(owner_name(owner)) + " '" + object.name + "' has no Texture");
}

void Analyzer::check_states(std::vector<StateAssignment>& states, StateOwner owner) {
  for (StateAssignment& state : states) {
    const StateRule* rule = find_state(owner, state.name);
    if (!rule) {
      diagnostics_.error(state.location, "unknown " + std::string(owner_name(owner)) + " state '" + state.name + "'");
      continue;
    }
    check_state_value(state, *rule);
  }
}

void Analyzer::check_state_value(StateAssignment& state, const StateRule& rule) {
  Expr& value = *state.value;
  using Kind = StateRule::Kind;
  if (rule.kind == Kind::kFunction) {
    const auto* overloads = find_functions(value.text);
    if (!overloads) diagnostics_.error(value.location, "unknown function '" + value.text + "' in " + state.name);
    else value.function = overloads->front();
    for (ExprPtr& size : state.thread_group) {
      check(*size);
      auto n = evaluate_integer_constant(*size);
      if (!n || *n < 1 || *n > 1024) diagnostics_.error(size->location, "thread group size must be a constant from 1 to 1024");
    }
    return;
  }
  if (rule.kind == Kind::kTexture || (rule.kind == Kind::kEnum && value.kind == ExprKind::kName)) {
    if (rule.kind == Kind::kEnum) {
      // Values are case-insensitive: public effects write CLAMP, Clamp and clamp alike.
      for (const std::string& name : *rule.values)
        if (same_ignoring_case(value.text, name)) return;
      diagnostics_.error(value.location, "'" + value.text + "' is not a value of " + state.name + " (" + joined(*rule.values) + ")");
      return;
    }
    value.variable = value.kind == ExprKind::kName ? find_variable(value.text) : nullptr;
    if (value.variable) value.resolved = value.variable->resolved;
    if (!value.variable || value.variable->resolved.base != BaseType::kTexture || value.variable->resolved.is_array())
      diagnostics_.error(value.location, "'" + state.name + "' must name a texture" +
                                             (value.kind == ExprKind::kName ? ", not '" + value.text + "'" : std::string()));
    return;
  }
  // TRUE and FALSE (any case), which ReShade takes as state values beside true and false
  // (SRGBTexture = FALSE), unless the effect declares a variable of that name.
  if (value.kind == ExprKind::kName && (same_ignoring_case(value.text, "true") || same_ignoring_case(value.text, "false")) &&
      !find_variable(value.text)) {
    value.kind = ExprKind::kBool;
    value.boolean = same_ignoring_case(value.text, "true");
  }
  check(value);
  if (is_error(value.resolved)) return;
  if (!value.resolved.is_scalar()) {
    diagnostics_.error(value.location, "'" + state.name + "' needs a number, not '" + type_name(value.resolved) + "'");
    return;
  }
  if (rule.kind != Kind::kSize && rule.kind != Kind::kMask && rule.kind != Kind::kEnum) return;
  auto n = evaluate_integer_constant(value);
  bool texture_size = state.name == "Width" || state.name == "Height" || state.name == "Depth";
  if (n && *n < 1 && (texture_size || state.name == "MipLevels")) {
    // BUFFER_HEIGHT / 256 on a small frame: ReShade makes such a texture 1 texel (or level) and
    // runs the effect, so pfx does too.
    diagnostics_.warning(value.location, "'" + state.name + "' is " + std::to_string(*n) + " at this frame size; 1 is used, as ReShade does");
    value = Expr{};
    value.kind = ExprKind::kInt;
    value.location = state.location;
    value.text = "1";
    value.number.kind = NumberLiteral::Kind::kInt;
    value.number.integer = 1;
    value.resolved = Type::scalar(BaseType::kInt);
    n = 1;
  }
  long long high = texture_size ? limits::kMaxTextureSize : rule.kind == Kind::kMask ? 255 : 1 << 24;
  long long low = rule.kind == Kind::kSize ? 1 : 0;
  if (!n || *n < low || *n > high)
    diagnostics_.error(value.location, "'" + state.name + "' must be an integer constant from " + std::to_string(low) +
                                           " to " + std::to_string(high));
}

}  // namespace pfx::fx
