#pragma once
// The intrinsic functions FX shaders call (HLSL's and ReShade's), with the type each returns for
// given argument types. What each one computes is the code generator's concern; here a call is
// checked for its argument count and kinds, and typed.
#include <string>
#include <vector>

#include "../ast/semantic_type.hpp"

namespace pfx::fx {

bool is_intrinsic(const std::string& name);

struct IntrinsicTyping {
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
