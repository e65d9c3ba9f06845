#pragma once
// Integer constant expressions after analysis: array sizes, thread group sizes, texture sizes,
// switch labels. Folded by evaluate_constant (constant_value.hpp) down to one number, a float
// truncated toward zero; nullopt for anything else.
#include <optional>

#include "../ast/ast.hpp"

namespace pfx::fx {

std::optional<long long> evaluate_integer_constant(const Expr& expression);

}  // namespace pfx::fx
