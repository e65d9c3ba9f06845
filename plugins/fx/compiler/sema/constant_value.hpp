#pragma once
// Constant values of any numeric shape, for what the runtime reads from the tree rather than from
// the GPU: uniform initialisers, annotations (ui_min = float2(0, 1)), texture sizes. Works on
// checked and unchecked expressions (annotations are not checked by the analyser), flattening
// vectors, matrices (row by row), arrays and initialiser lists into one list of components.
#include <optional>
#include <string>
#include <vector>

#include "../ast/ast.hpp"

namespace pfx::fx {

struct ConstantValue {
  std::vector<double> components;  // every scalar, in declaration order
  std::string text;                // a string literal's value (components then empty)
  bool is_string = false;
};

std::optional<ConstantValue> evaluate_constant(const Expr& expression);

}  // namespace pfx::fx
