#pragma once
// Typing a call of an intrinsic (ast/intrinsic.hpp has the table): its argument count and kinds
// are checked, and its result and parameter types given. What each one computes is the back
// ends' concern.
#include <string>
#include <vector>

#include "../ast/intrinsic.hpp"
#include "../ast/semantic_type.hpp"

namespace pfx::fx {

struct IntrinsicTyping {
  Intrinsic id = Intrinsic::kNone;
  Type result;
  // The type each argument converts to (the same length as the call's arguments); an argument
  // left as void keeps its own type (objects, out parameters).
  std::vector<Type> parameters;
  std::vector<bool> writes;  // out/inout arguments (sincos, modf, frexp, atomics on variables)
};

// False with `error` when the arguments do not fit.
bool type_intrinsic(const std::string& name, const std::vector<Type>& arguments, IntrinsicTyping& typing,
                    std::string& error);

}  // namespace pfx::fx
