// Types and qualifiers.
#include "../literals.hpp"
#include "parser.hpp"

namespace pfx::fx {
namespace {

const struct {
  const char* word;
  unsigned bit;
} kQualifiers[] = {{"static", kQualStatic},       {"const", kQualConst},
                   {"uniform", kQualUniform},     {"extern", kQualExtern},
                   {"groupshared", kQualGroupShared}, {"precise", kQualPrecise},
                   {"in", kQualIn},               {"out", kQualOut},
                   {"inout", kQualIn | kQualOut}, {"inline", kQualInline},
                   {"volatile", kQualVolatile},   {"row_major", kQualRowMajor},
                   {"column_major", kQualColumnMajor}, {"linear", kQualLinear},
                   {"nointerpolation", kQualNoInterpolation}, {"noperspective", kQualNoPerspective},
                   {"centroid", kQualCentroid},   {"sample", kQualSample},
                   {"shared", kQualShared}};

unsigned qualifier_bit(const Token& token) {
  if (token.kind != TokenKind::kIdentifier) return 0;
  for (const auto& entry : kQualifiers)
    if (token.text == entry.word) return entry.bit;
  return 0;
}

bool builtin_type_word(const std::string& word) {
  TypeSyntax scratch;
  return word == "void" || word == "string" || word == "vector" || word == "matrix" ||
         parse_numeric_type_name(word, scratch) || parse_object_type_name(word, scratch);
}

}  // namespace

bool Parser::at_type(std::size_t ahead) const {
  const Token& token = peek(ahead);
  if (token.kind != TokenKind::kIdentifier && !token.is(Punct::kColonColon)) return false;
  if (token.kind == TokenKind::kIdentifier && builtin_type_word(token.text)) return true;
  std::string name;
  std::size_t i = ahead;
  if (peek(i).is(Punct::kColonColon)) ++i;
  for (;;) {
    if (peek(i).kind != TokenKind::kIdentifier) return false;
    name += peek(i).text;
    if (!peek(i + 1).is(Punct::kColonColon)) break;
    name += "::";
    i += 2;
  }
  return struct_names_.count(name) > 0 || struct_names_.count(namespace_prefix_ + name) > 0;
}

bool Parser::at_declaration() const {
  // A qualifier counts only before a type or another qualifier: "sample" and "linear" are also
  // common variable names.
  std::size_t i = 0;
  while (qualifier_bit(peek(i)) && (at_type(i + 1) || qualifier_bit(peek(i + 1)) ||
                                    (peek(i + 1).kind == TokenKind::kIdentifier && peek(i + 2).kind == TokenKind::kIdentifier)))
    ++i;
  if (i > 0) return true;
  const Token& first = peek();
  if (first.kind != TokenKind::kIdentifier && !first.is(Punct::kColonColon)) return false;
  if (first.kind == TokenKind::kIdentifier && builtin_type_word(first.text)) {
    std::size_t after = 1;
    if (peek(1).is(Punct::kLess))  // vector<float, 3>, sampler2D<int>
      while (peek(after).kind != TokenKind::kEnd && !peek(after++).is(Punct::kGreater)) {}
    return !peek(after).is(Punct::kLeftParen);  // float3(...) starts an expression
  }
  // Name Name, or A::B Name: a declaration of a struct-typed variable.
  std::size_t k = first.is(Punct::kColonColon) ? 1 : 0;
  while (peek(k).kind == TokenKind::kIdentifier && peek(k + 1).is(Punct::kColonColon)) k += 2;
  return peek(k).kind == TokenKind::kIdentifier && peek(k + 1).kind == TokenKind::kIdentifier;
}

unsigned Parser::parse_qualifiers() {
  unsigned qualifiers = 0;
  while (unsigned bit = qualifier_bit(peek())) {
    bool before_type = at_type(1) || qualifier_bit(peek(1)) ||
                       (peek(1).kind == TokenKind::kIdentifier && peek(2).kind == TokenKind::kIdentifier);
    if (!before_type) break;
    qualifiers |= bit;
    advance();
  }
  return qualifiers;
}

bool Parser::parse_qualified_name(std::string& name) {
  name.clear();
  if (accept(Punct::kColonColon)) name = "::";
  std::string part;
  if (!expect_identifier(part, "a name")) return false;
  name += part;
  while (at(Punct::kColonColon) && peek(1).kind == TokenKind::kIdentifier) {
    advance();
    name += "::" + advance().text;
  }
  return true;
}

namespace {

bool small_integer(const Token& token, int low, int high, int& value) {
  std::string error;
  auto literal = token.kind == TokenKind::kNumber ? parse_number(token.text, error) : std::nullopt;
  if (!literal || (literal->kind != NumberLiteral::Kind::kInt && literal->kind != NumberLiteral::Kind::kUint))
    return false;
  value = static_cast<int>(literal->integer);
  return value >= low && value <= high;
}

}  // namespace

bool Parser::parse_type(TypeSyntax& type) {
  const Token& token = peek();
  if (token.kind != TokenKind::kIdentifier && !token.is(Punct::kColonColon)) {
    error_here("expected a type");
    return false;
  }
  std::string word = token.text;
  SourceLocation where = token.location;
  if (word == "vector" || word == "matrix") {
    advance();
    bool matrix = word == "matrix";
    type = TypeSyntax{};
    type.base = BaseType::kFloat;
    type.shape = matrix ? Shape::kMatrix : Shape::kVector;
    type.rows = 4;
    type.columns = matrix ? 4 : 1;
    if (!accept(Punct::kLess)) return true;
    TypeSyntax element;
    if (!parse_type(element)) return false;
    type.base = element.base;
    if (!expect(Punct::kComma, "in vector/matrix type")) return false;
    if (!small_integer(peek(), 1, 4, type.rows)) return error_here("expected a size from 1 to 4"), false;
    advance();
    if (matrix) {
      if (!expect(Punct::kComma, "in matrix type")) return false;
      if (!small_integer(peek(), 1, 4, type.columns)) return error_here("expected a size from 1 to 4"), false;
      advance();
    }
    return expect(Punct::kGreater, "after vector/matrix type arguments");
  }
  if (parse_numeric_type_name(word, type)) return advance(), true;
  if (parse_object_type_name(word, type)) {
    advance();
    if (type.base != BaseType::kTexture && accept(Punct::kLess)) {
      TypeSyntax element;
      if (!parse_type(element)) return false;
      if (!element.is_numeric() || element.shape == Shape::kMatrix) return error_at(where, "bad element type of '" + word + "'"), false;
      type.element_base = element.base;
      type.element_rows = element.shape == Shape::kVector ? element.rows : 1;
      return expect(Punct::kGreater, "after the element type");
    }
    return true;
  }
  type = TypeSyntax{};
  if (word == "void" || word == "string") {
    type.base = word == "void" ? BaseType::kVoid : BaseType::kString;
    return advance(), true;
  }
  type.base = BaseType::kStruct;
  return parse_qualified_name(type.struct_name);
}

}  // namespace pfx::fx
