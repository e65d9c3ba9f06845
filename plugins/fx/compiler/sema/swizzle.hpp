#pragma once
// Swizzles: "xyzw"/"rgba" on scalars and vectors (x.xxx, v.bgr), "_m00"/"_11" on matrices.
#include <string>
#include <vector>

#include "../ast/semantic_type.hpp"

namespace pfx::fx {

// Fills `components` (vector: 0..3; matrix: row * 4 + column) and returns true when `text` is a
// valid swizzle of `type`; otherwise false with `error` set.
bool parse_swizzle(const std::string& text, const Type& type, std::vector<int>& components, std::string& error);

}  // namespace pfx::fx
