// Uniform values written into the program as constants (a specialised program): the same bits the
// runtime would upload as a live uniform, as GLSL literals, so the driver can fold the branches and
// loops they control and the pictures stay the same.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "glsl_generator.hpp"
#include "glsl_writer.hpp"

namespace pfx::fx {
namespace {

// One component as the runtime uploads it: a float rounded to single precision, an int or a uint
// truncated, a bool from the int it would be uploaded as (`matrix`: of a float matrix).
std::string component(BaseType base, bool matrix, double value) {
  char text[48];
  if (matrix || (base != BaseType::kInt && base != BaseType::kUint && base != BaseType::kBool)) {
    // Nine significant digits give back the same single-precision float.
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(static_cast<float>(value)));
    std::string s = text;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
  }
  if (base == BaseType::kUint) {
    std::snprintf(text, sizeof text, "%uu", static_cast<std::uint32_t>(static_cast<long long>(value)));
    return text;
  }
  const auto integer = static_cast<std::int32_t>(value);
  if (base == BaseType::kBool) return integer != 0 ? "true" : "false";
  // INT_MIN has no literal of its own: its magnitude does not fit an int.
  if (integer == INT32_MIN) return "(-2147483647 - 1)";
  return std::to_string(integer);
}

// The value of `t` from values[*next] on, one component after another (a matrix row by row of
// the HLSL matrix, which is the GLSL constructor's order: see glsl_types.cpp).
std::string value_of(const GlslWriter& w, const Type& t, const std::vector<double>& values, std::size_t* next) {
  if (t.is_array()) {
    const Type element = t.element();
    std::string text = w.full_type(t) + "(";
    for (int i = 0; i < t.array.front(); ++i) text += (i ? ", " : "") + value_of(w, element, values, next);
    return text + ")";
  }
  if (held_as_rows(t)) {  // an array of rows of its own base type
    std::string text = w.type(t) + "(";
    for (int r = 0; r < t.rows; ++r) text += (r ? ", " : "") + value_of(w, row_of(t), values, next);
    return text + ")";
  }
  const bool matrix = t.shape == Shape::kMatrix;
  std::string text;
  for (int c = 0; c < t.components(); ++c) text += (c ? ", " : "") + component(t.base, matrix, values[(*next)++]);
  return t.shape == Shape::kScalar ? text : w.type(t) + "(" + text + ")";
}

std::size_t component_count(const Type& t) {
  std::size_t count = static_cast<std::size_t>(t.components());
  for (int size : t.array) count *= static_cast<std::size_t>(size);
  return count;
}

}  // namespace

bool can_be_constant(const Type& t, const std::vector<double>& values) {
  if (t.base != BaseType::kBool && t.base != BaseType::kInt && t.base != BaseType::kUint && t.base != BaseType::kFloat &&
      t.base != BaseType::kHalf && t.base != BaseType::kDouble)
    return false;
  for (int size : t.array)
    if (size <= 0) return false;
  if (values.size() != component_count(t)) return false;
  // A constant NaN or infinity would need a literal GLSL does not have; an integer outside what
  // its type holds would be converted differently here and in the upload, so it stays live.
  const bool float_matrix = t.shape == Shape::kMatrix && !held_as_rows(t);
  const bool integer = !float_matrix && (t.base == BaseType::kInt || t.base == BaseType::kBool);
  const bool unsigned_integer = !float_matrix && t.base == BaseType::kUint;
  for (double v : values) {
    if (!std::isfinite(static_cast<float>(v))) return false;
    if (integer && !(v > -2147483649.0 && v < 2147483648.0)) return false;
    if (unsigned_integer && !(v > -2147483649.0 && v < 4294967296.0)) return false;
  }
  return true;
}

std::string constant_initialiser(const GlslWriter& w, const Type& t, const std::vector<double>& values) {
  std::size_t next = 0;
  return value_of(w, t, values, &next);
}

}  // namespace pfx::fx
