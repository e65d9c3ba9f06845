// Expressions, with HLSL's meaning where GLSL's operators differ.
#include <cmath>
#include <cstdio>
#include <functional>

#include "glsl_identifiers.hpp"
#include "glsl_writer.hpp"

namespace pfx::fx {
namespace {

const char* comparison_function(Punct op) {
  switch (op) {
    case Punct::kLess: return "lessThan";
    case Punct::kGreater: return "greaterThan";
    case Punct::kLessEqual: return "lessThanEqual";
    case Punct::kGreaterEqual: return "greaterThanEqual";
    case Punct::kEqualEqual: return "equal";
    case Punct::kBangEqual: return "notEqual";
    default: return nullptr;
  }
}

Punct compound_base(Punct op) {
  switch (op) {
    case Punct::kPlusAssign: return Punct::kPlus;
    case Punct::kMinusAssign: return Punct::kMinus;
    case Punct::kStarAssign: return Punct::kStar;
    case Punct::kSlashAssign: return Punct::kSlash;
    case Punct::kPercentAssign: return Punct::kPercent;
    case Punct::kAmpAssign: return Punct::kAmp;
    case Punct::kPipeAssign: return Punct::kPipe;
    case Punct::kCaretAssign: return Punct::kCaret;
    case Punct::kShiftLeftAssign: return Punct::kShiftLeft;
    case Punct::kShiftRightAssign: return Punct::kShiftRight;
    default: return Punct::kNone;
  }
}

// `a op b` for operands of one type `t`, HLSL's way: '*' of matrices is per component, '%' is
// fmod for floats and truncating for signed integers.
std::string apply(Punct op, const std::string& a, const std::string& b, const Type& t, std::set<std::string>& helpers) {
  if (op == Punct::kStar && t.is_matrix()) return "matrixCompMult(" + a + ", " + b + ")";
  if (op == Punct::kPercent) {
    if (t.is_floating()) return helpers.insert("fmod"), "pfx_fmod(" + a + ", " + b + ")";
    if (t.base == BaseType::kInt) return helpers.insert("imod"), "pfx_imod(" + a + ", " + b + ")";
  }
  return "(" + a + " " + punct_spelling(op) + " " + b + ")";
}

// `m._m00_m11`: GLSL has no swizzles of matrices, so such a target is written element by element.
bool is_matrix_swizzle(const Expr& e) {
  return e.kind == ExprKind::kMember && e.swizzle.size() > 1 && e.operands[0]->resolved.is_matrix();
}

std::string element(const std::string& matrix, int index) {
  return matrix + "[" + std::to_string(index / 4) + "][" + std::to_string(index % 4) + "]";
}

}  // namespace

std::string GlslWriter::temporary(const Type& t) {
  std::string name = "t_" + std::to_string(temporary_count_++);
  temporary_declarations_ += type(t) + " " + name + array_suffix(t) + ";\n";
  return name;
}

std::string GlslWriter::take_temporaries(int indent) {
  std::string out, pad(static_cast<std::size_t>(indent) * 2, ' ');
  std::size_t start = 0;
  for (std::size_t end; (end = temporary_declarations_.find('\n', start)) != std::string::npos; start = end + 1)
    out += pad + temporary_declarations_.substr(start, end + 1 - start);
  temporary_declarations_.clear();
  return out;
}

std::string GlslWriter::name_of(const VariableDecl& v) const {
  if (const std::string* global = names_.of(&v)) return *global;
  return glsl_safe("l_" + v.name);
}

std::string GlslWriter::literal(const Expr& e) {
  if (e.kind == ExprKind::kBool) return e.boolean ? "true" : "false";
  if (e.kind == ExprKind::kInt) {
    std::uint32_t bits = static_cast<std::uint32_t>(e.number.integer);
    if (e.number.kind == NumberLiteral::Kind::kUint) return std::to_string(bits) + "u";
    if (bits > 0x7FFFFFFFu) return "int(" + std::to_string(bits) + "u)";
    return std::to_string(bits);
  }
  double v = e.number.real;
  float f = static_cast<float>(v);
  if (std::isinf(f)) return f > 0 ? "uintBitsToFloat(0x7F800000u)" : "uintBitsToFloat(0xFF800000u)";
  if (std::isnan(f)) return "uintBitsToFloat(0x7FC00000u)";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(f));
  std::string text = buffer;
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string GlslWriter::expr(const Expr& e) {
  switch (e.kind) {
    case ExprKind::kInt:
    case ExprKind::kFloat:
    case ExprKind::kBool: return literal(e);
    case ExprKind::kString: error(e.location, "a string cannot be a value in a shader"); return "0";
    case ExprKind::kName:
      if (!e.variable) return error(e.location, "'" + e.text + "' names no variable"), "0";
      return name_of(*e.variable);
    case ExprKind::kUnary:
    case ExprKind::kPostfix: return unary(e);
    case ExprKind::kBinary: return binary(e);
    case ExprKind::kAssign: return assignment(e);
    case ExprKind::kConditional: {
      std::string c = expr(*e.operands[0]), a = expr(*e.operands[1]), b = expr(*e.operands[2]);
      // A vector condition picks per component (and HLSL evaluates both sides anyway).
      if (e.operands[0]->resolved.is_vector()) return "mix(" + b + ", " + a + ", " + c + ")";
      return "(" + c + " ? " + a + " : " + b + ")";
    }
    case ExprKind::kSequence: {
      std::string text = "(";
      for (std::size_t i = 0; i < e.operands.size(); ++i) text += (i ? ", " : "") + expr(*e.operands[i]);
      return text + ")";
    }
    case ExprKind::kCall: return call(e);
    case ExprKind::kConstruct: return construct(e);
    case ExprKind::kCast: return cast(expr(*e.operands[0]), e.operands[0]->resolved, e.resolved);
    case ExprKind::kMember: return member(e);
    case ExprKind::kIndex: return expr(*e.operands[0]) + "[" + expr(*e.operands[1]) + "]";
    case ExprKind::kInitList: return init_list(e, e.resolved);
  }
  return "0";
}

std::string GlslWriter::unary(const Expr& e) {
  const Expr& operand = *e.operands[0];
  std::string x = expr(operand);
  bool steps = e.kind == ExprKind::kPostfix || e.op == Punct::kPlusPlus || e.op == Punct::kMinusMinus;
  if (steps && held_as_rows(operand.resolved)) return error(e.location, "++ and -- of an integer matrix are not supported"), x;
  if (e.kind == ExprKind::kPostfix) return "(" + x + punct_spelling(e.op) + ")";
  if (e.op == Punct::kBang) {
    Type as_bool = operand.resolved.with_base(BaseType::kBool);
    std::string b = cast(x, operand.resolved, as_bool);
    if (as_bool.is_matrix()) return by_rows(as_bool, as_bool, b, "", [](auto& row, auto&) { return "not(" + row + ")"; });
    return as_bool.is_vector() ? "not(" + b + ")" : "(!" + b + ")";
  }
  if (steps) return "(" + std::string(punct_spelling(e.op)) + x + ")";
  // -b and ~b of a bool compute on int, as HLSL does.
  std::string op = punct_spelling(e.op), value = cast(x, operand.resolved, e.resolved);
  if (held_as_rows(e.resolved)) return by_rows(e.resolved, e.resolved, value, "", [&](auto& row, auto&) { return "(" + op + row + ")"; });
  return "(" + op + value + ")";
}

std::string GlslWriter::binary(const Expr& e) {
  const Type& t = e.operands[0]->resolved;
  std::string a = expr(*e.operands[0]), b = expr(*e.operands[1]);
  if (const char* f = comparison_function(e.op)) {
    // Comparing matrices gives a bool matrix, held as rows.
    if (t.is_matrix()) return by_rows(t, e.resolved, a, b, [&](auto& x, auto& y) { return std::string(f) + "(" + x + ", " + y + ")"; });
    if (t.is_vector()) return std::string(f) + "(" + a + ", " + b + ")";
  }
  if ((e.op == Punct::kAmpAmp || e.op == Punct::kPipePipe) && (t.is_vector() || t.is_matrix())) {
    helpers.insert("logic");
    std::string f = e.op == Punct::kAmpAmp ? "pfx_and(" : "pfx_or(";
    if (t.is_vector()) return f + a + ", " + b + ")";
    return by_rows(e.resolved, e.resolved, cast(a, t, e.resolved), cast(b, t, e.resolved), [&](auto& x, auto& y) { return f + x + ", " + y + ")"; });
  }
  if (held_as_rows(t)) return by_rows(t, e.resolved, a, b, [&](auto& x, auto& y) { return apply(e.op, x, y, row_of(t), helpers); });
  return apply(e.op, a, b, t, helpers);
}

// `target = value`, where the target may be a matrix swizzle: the value is held once and its
// components written to the elements the swizzle names, and the expression's value is the value.
std::string GlslWriter::store(const Expr& target, const std::string& value) {
  if (!is_matrix_swizzle(target)) return "(" + expr(target) + " = " + value + ")";
  std::string held = temporary(target.resolved), matrix = expr(*target.operands[0]);
  std::string text = "(" + held + " = " + value;
  for (std::size_t i = 0; i < target.swizzle.size(); ++i) text += ", " + element(matrix, target.swizzle[i]) + " = " + held + "[" + std::to_string(i) + "]";
  return text + ", " + held + ")";
}

std::string GlslWriter::assignment(const Expr& e) {
  std::string target = expr(*e.operands[0]);
  std::string value = expr(*e.operands[1]);
  const Type& t = e.operands[0]->resolved;
  Punct base = compound_base(e.op);
  if (is_matrix_swizzle(*e.operands[0])) {
    if (e.op == Punct::kAssign) return store(*e.operands[0], value);
    return store(*e.operands[0], apply(base, target, value, t, helpers));
  }
  if (base != Punct::kNone && held_as_rows(t))
    return "(" + target + " = " + by_rows(t, t, target, value, [&](auto& x, auto& y) { return apply(base, x, y, row_of(t), helpers); }) + ")";
  bool rewrite = (base == Punct::kStar && t.is_matrix()) || (base == Punct::kPercent && (t.is_floating() || t.base == BaseType::kInt));
  if (rewrite) return "(" + target + " = " + apply(base, target, value, t, helpers) + ")";
  return "(" + target + " " + punct_spelling(e.op) + " " + value + ")";
}

std::string GlslWriter::member(const Expr& e) {
  const Expr& object = *e.operands[0];
  std::string x = expr(object);
  const Type& t = object.resolved;
  if (e.swizzle.empty()) return x + "." + glsl_safe("m_" + e.text);  // a struct member
  if (t.is_scalar()) {
    if (e.swizzle.size() == 1) return x;
    return type(e.resolved) + "(" + x + ")";
  }
  if (t.is_matrix()) {
    std::vector<std::string> parts;
    for (int index : e.swizzle) parts.push_back(element(x, index));
    if (parts.size() == 1) return parts[0];
    std::string text = type(e.resolved) + "(";
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
    return text + ")";
  }
  std::string letters;
  for (int index : e.swizzle) letters += "xyzw"[index & 3];
  return x + "." + letters;
}

std::string GlslWriter::call(const Expr& e) {
  if (e.intrinsic != Intrinsic::kNone) return intrinsic(e);
  if (!e.function) return error(e.location, "call to unknown function '" + e.text + "'"), "0";
  const std::string* name = names_.of(e.function);
  std::string text = (name ? *name : glsl_safe("F_" + e.text)) + "(";
  // An out or inout argument of another type than its parameter (or one GLSL cannot write to, a
  // matrix swizzle) goes through a temporary of the parameter's type: converted in before the
  // call, converted back and stored after it, as HLSL does.
  std::string before, after;
  std::size_t i = 0;
  for (; i < e.operands.size(); ++i) {
    const Expr& argument = *e.operands[i];
    const VariableDecl& p = e.function->parameters[i];
    std::string value;
    if ((p.qualifiers & kQualOut) && (!(argument.resolved == p.resolved) || is_matrix_swizzle(argument))) {
      value = temporary(p.resolved);
      if (p.qualifiers & kQualIn) before += value + " = " + cast(expr(argument), argument.resolved, p.resolved) + ", ";
      after += ", " + store(argument, cast(value, p.resolved, argument.resolved));
    } else {
      value = expr(argument);
    }
    text += (i ? ", " : "") + value;
  }
  // Parameters left out take their default values.
  for (; i < e.function->parameters.size(); ++i) {
    const VariableDecl& p = e.function->parameters[i];
    if (p.initializer) text += (i ? ", " : "") + cast(expr(*p.initializer), p.initializer->resolved, p.resolved);
  }
  text += ")";
  if (before.empty() && after.empty()) return text;
  if (e.resolved.is_void()) return "(" + before + text + after + ")";
  std::string result = temporary(e.resolved);
  return "(" + before + result + " = " + text + after + ", " + result + ")";
}

std::string GlslWriter::construct(const Expr& e) {
  const Type& t = e.resolved;
  if (e.operands.size() == 1 && e.operands[0]->resolved.is_scalar()) return cast(expr(*e.operands[0]), e.operands[0]->resolved, t);
  // A matrix held as rows, or made from one, is regrouped from its arguments' components.
  bool rows = held_as_rows(t);
  for (const ExprPtr& argument : e.operands) rows = rows || (t.is_matrix() && held_as_rows(argument->resolved));
  if (rows) return init_list(e, t);
  std::string text = type(t) + "(";
  for (std::size_t i = 0; i < e.operands.size(); ++i) {
    const Expr& argument = *e.operands[i];
    std::string value = expr(argument);
    if (argument.resolved.is_floating() && !argument.resolved.is_matrix() && (t.base == BaseType::kInt || t.base == BaseType::kUint))
      value = cast(value, argument.resolved, argument.resolved.with_base(t.base));  // HLSL's saturating conversion
    // GLSL takes a matrix argument only in a matrix constructor; elsewhere spell out its rows.
    if (argument.resolved.is_matrix() && !t.is_matrix()) {
      std::string rows;
      for (int r = 0; r < argument.resolved.rows; ++r) rows += (r ? ", " : "") + std::string("(") + value + ")[" + std::to_string(r) + "]";
      value = rows;
    }
    text += (i ? ", " : "") + value;
  }
  return text + ")";
}

// Initialiser lists: HLSL flattens braces, so the leaves are read as one stream of components and
// regrouped into GLSL constructors of the target's shape.
std::string GlslWriter::init_list(const Expr& list, const Type& target) {
  struct Leaf {
    std::string text;
    Type type;
  };
  std::vector<Leaf> leaves;
  // Depth-first, left to right.
  std::function<void(const Expr&)> collect = [&](const Expr& e) {
    for (const ExprPtr& operand : e.operands) {
      if (operand->kind == ExprKind::kInitList) collect(*operand);
      else leaves.push_back({expr(*operand), operand->resolved});
    }
  };
  collect(list);
  std::size_t leaf = 0;
  int offset = 0;  // components of leaves[leaf] already used
  // The next component as a `base` scalar.
  auto component = [&](BaseType base) -> std::string {
    if (leaf >= leaves.size()) return type(Type::scalar(base)) + "(0)";
    const Leaf& l = leaves[leaf];
    std::string text;
    if (l.type.is_scalar()) text = l.text;
    else if (l.type.is_matrix()) text = "(" + l.text + ")[" + std::to_string(offset / l.type.columns) + "][" + std::to_string(offset % l.type.columns) + "]";
    else text = "(" + l.text + ")[" + std::to_string(offset) + "]";
    Type from = Type::scalar(l.type.base);
    if (++offset >= std::max(1, l.type.components())) ++leaf, offset = 0;
    return cast(text, from, Type::scalar(base));
  };
  std::function<std::string(const Type&)> build = [&](const Type& t) -> std::string {
    if (t.is_array()) {
      Type element = t.element();
      std::string text = full_type(t) + "(";
      for (int i = 0; i < t.array[0]; ++i) text += (i ? ", " : "") + build(element);
      return text + ")";
    }
    if (t.base == BaseType::kStruct && t.structure) {
      std::string text = type(t) + "(";
      for (std::size_t i = 0; i < t.structure->fields.size(); ++i) text += (i ? ", " : "") + build(t.structure->fields[i].resolved);
      return text + ")";
    }
    // A whole leaf of exactly this type is used as it is.
    if (leaf < leaves.size() && offset == 0 && leaves[leaf].type == t) return leaves[leaf++].text;
    if (leaf < leaves.size() && offset == 0 && leaves[leaf].type.components() == t.components() && leaves[leaf].type.is_numeric()) {
      const Leaf& l = leaves[leaf++];
      return cast(l.text, l.type, t);
    }
    std::string text = type(t) + "(";
    if (held_as_rows(t)) {
      for (int r = 0; r < t.rows; ++r) {
        text += (r ? ", " : "") + type(row_of(t)) + "(";
        for (int c = 0; c < t.columns; ++c) text += (c ? ", " : "") + component(t.base);
        text += ")";
      }
      return text + ")";
    }
    for (int i = 0; i < t.components(); ++i) text += (i ? ", " : "") + component(t.base);
    return text + ")";
  };
  return build(target);
}

}  // namespace pfx::fx
