#include "semantic_type.hpp"

#include "ast.hpp"

namespace pfx::fx {

bool Type::operator==(const Type& o) const {
  if (base != o.base || array != o.array) return false;
  if (base == BaseType::kStruct) return structure == o.structure;
  if (is_object() || o.is_object())
    return dimension == o.dimension && (base == BaseType::kTexture || (element_base == o.element_base && element_rows == o.element_rows));
  if (base == BaseType::kVoid || base == BaseType::kString) return true;
  return shape == o.shape && rows == o.rows && columns == o.columns;
}

std::string type_name(const Type& type) {
  TypeSyntax syntax;
  syntax.base = type.base;
  syntax.shape = type.shape;
  syntax.rows = type.rows;
  syntax.columns = type.columns;
  syntax.dimension = type.dimension;
  syntax.element_base = type.element_base;
  syntax.element_rows = type.element_rows;
  if (type.structure) syntax.struct_name = type.structure->name;
  std::string text = type_spelling(syntax);
  for (int size : type.array) text += "[" + (size > 0 ? std::to_string(size) : std::string()) + "]";
  return text;
}

}  // namespace pfx::fx
