#pragma once
// HLSL's implicit conversions and the result types of operators: scalar splat, vector and matrix
// truncation, and bool/int/uint/half/float/double converting in every direction.
#include <optional>

#include "../ast/semantic_type.hpp"

namespace pfx::fx {

struct Conversion {
  int cost = 0;           // 0 exact; more for a base change, a splat, a truncation (overload ranking)
  bool truncates = false;  // drops components: HLSL warns
};

// nullopt when `from` cannot become `to` implicitly.
std::optional<Conversion> implicit_conversion(const Type& from, const Type& to);

// Whether an explicit cast (T)x is allowed (numeric casts also between equal component counts).
bool explicit_conversion(const Type& from, const Type& to);

// The type both operands of an arithmetic, bitwise or comparison operator convert to; nullopt
// when the shapes cannot be combined (a vector with a matrix of another size...). `truncates`
// is set when a vector or matrix operand loses components.
std::optional<Type> common_type(const Type& a, const Type& b, bool& truncates);

int base_rank(BaseType base);

}  // namespace pfx::fx
