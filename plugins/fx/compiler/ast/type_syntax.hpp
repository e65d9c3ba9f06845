#pragma once
// A type as written in FX source: a scalar, vector or matrix of a base type, a struct by name, or
// a texture/sampler/storage object. Array sizes belong to declarators, not to the type.
#include <string>

namespace pfx::fx {

enum class BaseType { kVoid, kBool, kInt, kUint, kFloat, kHalf, kDouble, kString, kStruct, kTexture, kSampler, kStorage };
enum class Shape { kScalar, kVector, kMatrix };

struct TypeSyntax {
  BaseType base = BaseType::kVoid;
  Shape shape = Shape::kScalar;
  int rows = 1;  // vector length, or matrix rows
  int columns = 1;
  std::string struct_name;  // kStruct: as written, possibly qualified ("A::B")
  // Objects: dimension 1..3 and, for samplers and storages, the element type (<int>, <float4>).
  int dimension = 2;
  BaseType element_base = BaseType::kFloat;
  int element_rows = 4;

  bool is_object() const { return base == BaseType::kTexture || base == BaseType::kSampler || base == BaseType::kStorage; }
  bool is_numeric() const {
    return base == BaseType::kBool || base == BaseType::kInt || base == BaseType::kUint || base == BaseType::kFloat ||
           base == BaseType::kHalf || base == BaseType::kDouble;
  }
};

// "float", "int3", "half4x4", "uint2x3", "bool", "dword": fills `type` and returns true.
bool parse_numeric_type_name(const std::string& word, TypeSyntax& type);
// "texture2D", "sampler", "storage3D": fills `type` and returns true.
bool parse_object_type_name(const std::string& word, TypeSyntax& type);
// The canonical spelling: "float3x2", "sampler2D<int>", a struct's name.
std::string type_spelling(const TypeSyntax& type);
const char* base_type_spelling(BaseType base);

}  // namespace pfx::fx
