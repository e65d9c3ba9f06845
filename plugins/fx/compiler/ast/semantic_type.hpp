#pragma once
// A checked type, as semantic analysis stores it on every expression of the tree: numeric
// scalar/vector/matrix, struct, object (texture, sampler, storage), string or void, with array
// dimensions.
#include <string>
#include <vector>

#include "type_syntax.hpp"

namespace pfx::fx {

struct StructDecl;

struct Type {
  BaseType base = BaseType::kVoid;
  Shape shape = Shape::kScalar;
  int rows = 1;     // vector length or matrix rows
  int columns = 1;  // matrix columns
  const StructDecl* structure = nullptr;
  int dimension = 2;  // objects
  BaseType element_base = BaseType::kFloat;
  int element_rows = 4;
  std::vector<int> array;  // outermost first; 0 for an unsized dimension

  static Type scalar(BaseType base) {
    Type t;
    t.base = base;
    return t;
  }
  static Type vector(BaseType base, int size) {
    Type t = scalar(base);
    if (size > 1) t.shape = Shape::kVector, t.rows = size;
    return t;
  }
  static Type matrix(BaseType base, int rows, int columns) {
    Type t = scalar(base);
    t.shape = Shape::kMatrix;
    t.rows = rows;
    t.columns = columns;
    return t;
  }

  bool is_array() const { return !array.empty(); }
  bool is_numeric() const {
    return !is_array() && (base == BaseType::kBool || base == BaseType::kInt || base == BaseType::kUint ||
                           base == BaseType::kFloat || base == BaseType::kHalf || base == BaseType::kDouble);
  }
  bool is_integral() const { return is_numeric() && (base == BaseType::kInt || base == BaseType::kUint || base == BaseType::kBool); }
  bool is_floating() const { return is_numeric() && (base == BaseType::kFloat || base == BaseType::kHalf || base == BaseType::kDouble); }
  bool is_scalar() const { return is_numeric() && shape == Shape::kScalar; }
  bool is_vector() const { return is_numeric() && shape == Shape::kVector; }
  bool is_matrix() const { return is_numeric() && shape == Shape::kMatrix; }
  bool is_object() const {
    return !is_array() && (base == BaseType::kTexture || base == BaseType::kSampler || base == BaseType::kStorage);
  }
  bool is_void() const { return base == BaseType::kVoid && !is_array(); }
  int components() const { return shape == Shape::kMatrix ? rows * columns : shape == Shape::kVector ? rows : 1; }
  Type element() const {  // one level of array removed
    Type t = *this;
    if (!t.array.empty()) t.array.erase(t.array.begin());
    return t;
  }
  Type with_base(BaseType b) const {
    Type t = *this;
    t.base = b;
    return t;
  }

  bool operator==(const Type& o) const;
  bool operator!=(const Type& o) const { return !(*this == o); }
};

// "float3", "float3x2", "S", "float[4]", "sampler2D<int>".
std::string type_name(const Type& type);

}  // namespace pfx::fx
