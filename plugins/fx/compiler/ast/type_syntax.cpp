#include "type_syntax.hpp"

namespace pfx::fx {
namespace {

bool scalar_base(const std::string& word, BaseType& base) {
  static const struct {
    const char* word;
    BaseType base;
  } table[] = {{"bool", BaseType::kBool},   {"int", BaseType::kInt},       {"uint", BaseType::kUint},
               {"dword", BaseType::kUint},  {"float", BaseType::kFloat},   {"half", BaseType::kHalf},
               {"double", BaseType::kDouble}, {"min16float", BaseType::kFloat}, {"min16int", BaseType::kInt},
               {"min16uint", BaseType::kUint}};
  for (const auto& entry : table)
    if (word == entry.word) return base = entry.base, true;
  return false;
}

}  // namespace

bool parse_numeric_type_name(const std::string& word, TypeSyntax& type) {
  // Split "float3x2" into "float", 3, 2 (the digits at the end).
  std::size_t end = word.size();
  int columns = 0, rows = 0;
  bool matrix = false;
  if (end >= 3 && word[end - 2] == 'x' && word[end - 1] >= '1' && word[end - 1] <= '4' && word[end - 3] >= '1' &&
      word[end - 3] <= '4') {
    rows = word[end - 3] - '0';
    columns = word[end - 1] - '0';
    matrix = true;
    end -= 3;
  } else if (end >= 1 && word[end - 1] >= '1' && word[end - 1] <= '4') {
    rows = word[end - 1] - '0';
    end -= 1;
  }
  BaseType base;
  if (!scalar_base(word.substr(0, end), base)) return false;
  type = TypeSyntax{};
  type.base = base;
  if (matrix) {
    type.shape = Shape::kMatrix;
    type.rows = rows;
    type.columns = columns;
  } else if (rows > 0) {
    type.shape = Shape::kVector;
    type.rows = rows;
  }
  return true;
}

bool parse_object_type_name(const std::string& word, TypeSyntax& type) {
  static const struct {
    const char* prefix;
    BaseType base;
  } table[] = {{"texture", BaseType::kTexture}, {"sampler", BaseType::kSampler}, {"storage", BaseType::kStorage}};
  for (const auto& entry : table) {
    std::string prefix = entry.prefix;
    if (word.compare(0, prefix.size(), prefix) != 0) continue;
    std::string rest = word.substr(prefix.size());
    int dimension = rest.empty() ? 2 : rest == "1D" ? 1 : rest == "2D" ? 2 : rest == "3D" ? 3 : 0;
    if (dimension == 0) return false;
    type = TypeSyntax{};
    type.base = entry.base;
    type.dimension = dimension;
    return true;
  }
  return false;
}

const char* base_type_spelling(BaseType base) {
  switch (base) {
    case BaseType::kVoid: return "void";
    case BaseType::kBool: return "bool";
    case BaseType::kInt: return "int";
    case BaseType::kUint: return "uint";
    case BaseType::kFloat: return "float";
    case BaseType::kHalf: return "half";
    case BaseType::kDouble: return "double";
    case BaseType::kString: return "string";
    case BaseType::kStruct: return "struct";
    case BaseType::kTexture: return "texture";
    case BaseType::kSampler: return "sampler";
    case BaseType::kStorage: return "storage";
  }
  return "?";
}

std::string type_spelling(const TypeSyntax& type) {
  if (type.base == BaseType::kStruct) return type.struct_name;
  std::string text = base_type_spelling(type.base);
  if (type.is_object()) {
    text += std::to_string(type.dimension) + "D";
    bool default_element = type.element_base == BaseType::kFloat && type.element_rows == 4;
    if (type.base != BaseType::kTexture && !default_element) {
      text += "<";
      text += base_type_spelling(type.element_base);
      if (type.element_rows > 1) text += std::to_string(type.element_rows);
      text += ">";
    }
    return text;
  }
  if (type.shape == Shape::kVector) text += std::to_string(type.rows);
  if (type.shape == Shape::kMatrix) text += std::to_string(type.rows) + "x" + std::to_string(type.columns);
  return text;
}

}  // namespace pfx::fx
