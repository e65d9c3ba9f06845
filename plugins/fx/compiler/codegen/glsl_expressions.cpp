// Expressions, with HLSL's meaning where GLSL's operators differ.
#include <cmath>
#include <cstdio>
#include <functional>

#include "../model/glsl_identifiers.hpp"
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

}  // namespace

std::string GlslWriter::name_of(const VariableDecl& v) const {
  auto it = model_.global_names.find(&v);
  if (it != model_.global_names.end()) return it->second;
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
  if (e.kind == ExprKind::kPostfix) return "(" + x + punct_spelling(e.op) + ")";
  if (e.op == Punct::kBang) {
    Type as_bool = operand.resolved.with_base(BaseType::kBool);
    std::string b = cast(x, operand.resolved, as_bool);
    return as_bool.is_vector() ? "not(" + b + ")" : "(!" + b + ")";
  }
  if (e.op == Punct::kPlusPlus || e.op == Punct::kMinusMinus) return "(" + std::string(punct_spelling(e.op)) + x + ")";
  // -b and ~b of a bool compute on int, as HLSL does.
  return "(" + std::string(punct_spelling(e.op)) + cast(x, operand.resolved, e.resolved) + ")";
}

std::string GlslWriter::binary(const Expr& e) {
  const Type& t = e.operands[0]->resolved;
  std::string a = expr(*e.operands[0]), b = expr(*e.operands[1]);
  if (const char* f = comparison_function(e.op)) {
    if (t.is_matrix()) return error(e.location, "comparing matrices is not supported"), "false";
    if (t.is_vector()) return std::string(f) + "(" + a + ", " + b + ")";
  }
  if ((e.op == Punct::kAmpAmp || e.op == Punct::kPipePipe) && t.is_vector()) {
    helpers.insert("logic");
    return std::string(e.op == Punct::kAmpAmp ? "pfx_and(" : "pfx_or(") + a + ", " + b + ")";
  }
  return apply(e.op, a, b, t, helpers);
}

std::string GlslWriter::assignment(const Expr& e) {
  std::string target = expr(*e.operands[0]);
  std::string value = expr(*e.operands[1]);
  const Type& t = e.operands[0]->resolved;
  Punct base = compound_base(e.op);
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
    for (int index : e.swizzle) parts.push_back(x + "[" + std::to_string(index / 4) + "][" + std::to_string(index % 4) + "]");
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
  if (!e.intrinsic.empty()) return intrinsic(e);
  if (!e.function) return error(e.location, "call to unknown function '" + e.text + "'"), "0";
  auto it = model_.function_names.find(e.function);
  std::string text = (it != model_.function_names.end() ? it->second : glsl_safe("F_" + e.text)) + "(";
  std::size_t i = 0;
  for (; i < e.operands.size(); ++i) text += (i ? ", " : "") + expr(*e.operands[i]);
  // Parameters left out take their default values.
  for (; i < e.function->parameters.size(); ++i) {
    const VariableDecl& p = e.function->parameters[i];
    if (p.initializer) text += (i ? ", " : "") + cast(expr(*p.initializer), p.initializer->resolved, p.resolved);
  }
  return text + ")";
}

std::string GlslWriter::construct(const Expr& e) {
  const Type& t = e.resolved;
  if (e.operands.size() == 1 && e.operands[0]->resolved.is_scalar()) return splat(expr(*e.operands[0]), t);
  std::string text = type(t) + "(";
  for (std::size_t i = 0; i < e.operands.size(); ++i) {
    const Expr& argument = *e.operands[i];
    std::string value = expr(argument);
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
  auto component = [&]() -> std::string {
    if (leaf >= leaves.size()) return "0";
    const Leaf& l = leaves[leaf];
    std::string text;
    if (l.type.is_scalar()) text = l.text;
    else if (l.type.is_matrix()) text = "(" + l.text + ")[" + std::to_string(offset / l.type.columns) + "][" + std::to_string(offset % l.type.columns) + "]";
    else text = "(" + l.text + ")[" + std::to_string(offset) + "]";
    if (++offset >= std::max(1, l.type.components())) ++leaf, offset = 0;
    return text;
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
    Type scalar = Type::scalar(t.base);
    for (int i = 0; i < t.components(); ++i) text += (i ? ", " : "") + type(scalar) + "(" + component() + ")";
    return text + ")";
  };
  return build(target);
}

}  // namespace pfx::fx
