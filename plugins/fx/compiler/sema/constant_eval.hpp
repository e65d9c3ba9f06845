#pragma once
// Integer constant expressions after analysis: array sizes, thread group sizes. Literals, static
// const variables with constant initialisers, casts and arithmetic; nullopt for anything else.
#include <optional>

#include "../ast/ast.hpp"

namespace pfx::fx {

std::optional<long long> evaluate_integer_constant(const Expr& expression);

}  // namespace pfx::fx
