#include "constant_eval.hpp"

#include <cmath>

#include "constant_value.hpp"

namespace pfx::fx {

// Whatever shape the expression has on the way (swizzles of constant vectors, members, casts,
// comparisons, bit operations, conditionals), as long as it ends in one number; a float is
// truncated toward zero, as ReShade converts a texture's Width = BUFFER_WIDTH / 3.0.
std::optional<long long> evaluate_integer_constant(const Expr& expression) {
  const std::optional<ConstantValue> value = evaluate_constant(expression);
  if (!value || value->is_string || value->components.size() != 1) return std::nullopt;
  const double number = std::trunc(value->components[0]);
  if (!std::isfinite(number) || std::fabs(number) > 9.0e15) return std::nullopt;
  return static_cast<long long>(number);
}

}  // namespace pfx::fx
