// GLSL spellings of FX types, and HLSL's conversions between them.
#include "glsl_writer.hpp"

namespace pfx::fx {
namespace {

const char* scalar_name(BaseType base) {
  switch (base) {
    case BaseType::kBool: return "bool";
    case BaseType::kInt: return "int";
    case BaseType::kUint: return "uint";
    default: return "float";  // half and double compute as float, as ReShade does
  }
}

const char* vector_prefix(BaseType base) {
  switch (base) {
    case BaseType::kBool: return "bvec";
    case BaseType::kInt: return "ivec";
    case BaseType::kUint: return "uvec";
    default: return "vec";
  }
}

const char* object_prefix(BaseType element) {
  return element == BaseType::kInt ? "i" : element == BaseType::kUint ? "u" : "";
}

}  // namespace

bool held_as_rows(const Type& t) {
  return t.is_matrix() && (t.base == BaseType::kInt || t.base == BaseType::kUint || t.base == BaseType::kBool);
}

std::string GlslWriter::type(const Type& t) const {
  switch (t.base) {
    case BaseType::kVoid: return "void";
    case BaseType::kStruct: {
      const std::string* name = t.structure ? names_.of(t.structure) : nullptr;
      return name ? *name : "void";
    }
    case BaseType::kSampler: return std::string(object_prefix(t.element_base)) + "sampler" + std::to_string(t.dimension) + "D";
    case BaseType::kStorage: return std::string(object_prefix(t.element_base)) + "image" + std::to_string(t.dimension) + "D";
    case BaseType::kTexture:
    case BaseType::kString: return "void";
    default: break;
  }
  if (t.shape == Shape::kScalar) return scalar_name(t.base);
  if (t.shape == Shape::kVector) return vector_prefix(t.base) + std::to_string(t.rows);
  if (held_as_rows(t)) return vector_prefix(t.base) + std::to_string(t.columns) + "[" + std::to_string(t.rows) + "]";
  // HLSL floatRxC is GLSL matRxC: R columns (HLSL's rows) of C components.
  return t.rows == t.columns ? "mat" + std::to_string(t.rows) : "mat" + std::to_string(t.rows) + "x" + std::to_string(t.columns);
}

std::string GlslWriter::array_suffix(const Type& t) const {
  std::string out;
  for (int size : t.array) out += "[" + std::to_string(size) + "]";
  return out;
}

std::string GlslWriter::full_type(const Type& t) const { return type(t) + array_suffix(t); }

std::string GlslWriter::splat(const std::string& scalar, const Type& to) {
  if (to.is_scalar()) return type(to) + "(" + scalar + ")";
  if (to.is_vector()) return type(to) + "(" + scalar + ")";
  if (held_as_rows(to)) {
    std::string text = type(to) + "(";
    for (int r = 0; r < to.rows; ++r) text += (r ? ", " : "") + type(row_of(to)) + "(" + scalar + ")";
    return text + ")";
  }
  // GLSL's mat(x) puts x on the diagonal only; HLSL's (float2x2)x fills every component.
  std::string text = type(to) + "(";
  for (int i = 0; i < to.components(); ++i) text += (i ? ", float(" : "float(") + scalar + ")";
  return text + ")";
}

std::string GlslWriter::cast(const std::string& text, const Type& from, const Type& to) {
  if (from == to) return text;
  if (!from.is_numeric() || !to.is_numeric()) return text;  // structs and arrays convert only to themselves
  if (from.is_floating() && (to.base == BaseType::kInt || to.base == BaseType::kUint)) {
    // To an integer of the same shape first, as HLSL converts (pfx_ftoi and pfx_ftou in the prelude).
    std::string helper = to.base == BaseType::kInt ? "pfx_ftoi" : "pfx_ftou";
    helpers.insert(helper.substr(4));
    Type integral = from.with_base(to.base);
    if (from.is_matrix()) return cast(by_rows(from, integral, text, "", [&](auto& row, auto&) { return helper + "(" + row + ")"; }), integral, to);
    return cast(helper + "(" + text + ")", integral, to);
  }
  if (from.is_scalar()) return splat(text, to);
  if (to.is_scalar()) {
    std::string first = from.is_matrix() ? "(" + text + ")[0][0]" : "(" + text + ").x";
    return from.base == to.base ? first : type(to) + "(" + first + ")";
  }
  if (to.is_matrix() && (held_as_rows(from) || held_as_rows(to))) {
    // Row by row from a copy: the upper-left part of a matrix, or a vector's components in order.
    std::string held = temporary(from), out = "(" + held + " = " + text + ", " + type(to) + "(";
    for (int r = 0; r < to.rows; ++r) {
      if (from.is_matrix()) {
        out += (r ? ", " : "") + type(row_of(to)) + "(" + held + "[" + std::to_string(r) + "])";
        continue;
      }
      out += (r ? ", " : "") + type(row_of(to)) + "(";
      for (int c = 0; c < to.columns; ++c) out += (c ? ", " : "") + held + "[" + std::to_string(r * to.columns + c) + "]";
      out += ")";
    }
    return out + "))";
  }
  if (to.is_matrix()) {
    if (from.is_matrix()) return type(to) + "(" + text + ")";  // the upper-left part, as in HLSL
    // A vector of as many components fills the matrix row by row; GLSL reads it column by column,
    // which is the same order here (a GLSL column is an HLSL row).
    return type(to) + "(" + cast(text, from, Type::vector(BaseType::kFloat, from.rows)) + ")";
  }
  if (from.is_matrix()) {  // to a vector: the matrix's components row by row
    std::string parts;
    for (int r = 0; r < from.rows; ++r) parts += (r ? ", " : "") + std::string("(") + text + ")[" + std::to_string(r) + "]";
    return type(to) + "(" + type(Type::vector(to.base, from.components())) + "(" + parts + "))";
  }
  return type(to) + "(" + text + ")";  // GLSL truncates a longer vector and converts the base
}

std::string GlslWriter::by_rows(const Type& t, const Type& result, const std::string& a, const std::string& b,
                                const std::function<std::string(const std::string&, const std::string&)>& row) {
  std::string x = temporary(t), y = b.empty() ? std::string() : temporary(t);
  std::string text = "(" + x + " = " + a + ", " + (y.empty() ? std::string() : y + " = " + b + ", ") + type(result) + "(";
  for (int r = 0; r < t.rows; ++r) {
    std::string i = "[" + std::to_string(r) + "]";
    text += (r ? ", " : "") + row(x + i, y.empty() ? y : y + i);
  }
  return text + "))";
}

}  // namespace pfx::fx
