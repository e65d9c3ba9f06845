#include "conversions.hpp"

#include <algorithm>

namespace pfx::fx {

int base_rank(BaseType base) {
  switch (base) {
    case BaseType::kBool: return 0;
    case BaseType::kInt: return 1;
    case BaseType::kUint: return 2;
    case BaseType::kHalf: return 3;
    case BaseType::kFloat: return 4;
    case BaseType::kDouble: return 5;
    default: return -1;
  }
}

std::optional<Conversion> implicit_conversion(const Type& from, const Type& to) {
  if (from == to) return Conversion{};
  if (from.is_array() || to.is_array() || from.base == BaseType::kStruct || to.base == BaseType::kStruct)
    return std::nullopt;
  if (from.is_object() || to.is_object()) {
    // A sampler/storage of one element type is not another; textures have none.
    if (from.base != to.base || from.dimension != to.dimension) return std::nullopt;
    return Conversion{};
  }
  if (!from.is_numeric() || !to.is_numeric()) return std::nullopt;
  Conversion c;
  if (from.base != to.base) c.cost += 1;
  if (from.components() == 1 && to.components() > 1) return c.cost += 2, c;  // splat
  if (to.is_scalar()) {
    if (from.components() > 1) c.cost += 4, c.truncates = true;
    return c;
  }
  if (from.shape == to.shape) {
    if (from.rows < to.rows || (to.is_matrix() && from.columns < to.columns)) return std::nullopt;
    if (from.rows > to.rows || (to.is_matrix() && from.columns > to.columns)) c.cost += 3, c.truncates = true;
    return c;
  }
  // A vector and a matrix of the same number of components (float4 and float2x2).
  if (from.components() == to.components()) return c.cost += 3, c;
  if (from.is_vector() && to.is_matrix() && to.rows == 1 && from.rows >= to.columns) return c.cost += 3, c;
  if (from.is_matrix() && from.rows == 1 && to.is_vector() && from.columns >= to.rows) return c.cost += 3, c;
  return std::nullopt;
}

bool explicit_conversion(const Type& from, const Type& to) {
  if (implicit_conversion(from, to)) return true;
  return from.is_numeric() && to.is_numeric() && from.components() == to.components();
}

std::optional<Type> common_type(const Type& a, const Type& b, bool& truncates) {
  truncates = false;
  if (!a.is_numeric() || !b.is_numeric()) return std::nullopt;
  BaseType base = base_rank(a.base) >= base_rank(b.base) ? a.base : b.base;
  if (a.components() == 1 && !a.is_matrix()) return b.with_base(base);
  if (b.components() == 1 && !b.is_matrix()) return a.with_base(base);
  if (a.shape != b.shape) {
    if (a.components() == b.components()) return a.with_base(base);
    return std::nullopt;
  }
  Type result = a.with_base(base);
  result.rows = std::min(a.rows, b.rows);
  result.columns = std::min(a.columns, b.columns);
  truncates = a.rows != b.rows || a.columns != b.columns;
  return result;
}

}  // namespace pfx::fx
