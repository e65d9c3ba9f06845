// Expressions: literals, names, operators, members and swizzles, indexing, constructors, casts,
// initialiser lists, and the implicit conversions between them.
#include "analyzer.hpp"
#include "conversions.hpp"
#include "swizzle.hpp"

namespace pfx::fx {
namespace {

bool is_comparison(Punct op) {
  return op == Punct::kLess || op == Punct::kGreater || op == Punct::kLessEqual || op == Punct::kGreaterEqual ||
         op == Punct::kEqualEqual || op == Punct::kBangEqual;
}

bool is_bitwise(Punct op) {
  return op == Punct::kAmp || op == Punct::kPipe || op == Punct::kCaret || op == Punct::kShiftLeft ||
         op == Punct::kShiftRight || op == Punct::kAmpAssign || op == Punct::kPipeAssign || op == Punct::kCaretAssign ||
         op == Punct::kShiftLeftAssign || op == Punct::kShiftRightAssign;
}

}  // namespace

void Analyzer::check(Expr& e) {
  e.resolved = error_type();
  if (diagnostics_.too_many_errors()) return;
  switch (e.kind) {
    case ExprKind::kInt:
      e.resolved = Type::scalar(e.number.kind == NumberLiteral::Kind::kUint ? BaseType::kUint : BaseType::kInt);
      return;
    case ExprKind::kFloat:
      e.resolved = Type::scalar(e.number.kind == NumberLiteral::Kind::kHalf     ? BaseType::kHalf
                                : e.number.kind == NumberLiteral::Kind::kDouble ? BaseType::kDouble
                                                                                : BaseType::kFloat);
      return;
    case ExprKind::kBool: e.resolved = Type::scalar(BaseType::kBool); return;
    case ExprKind::kString: e.resolved = Type::scalar(BaseType::kString); return;
    case ExprKind::kName: check_name(e); return;
    case ExprKind::kUnary:
    case ExprKind::kPostfix: check_unary(e); return;
    case ExprKind::kBinary: check_binary(e); return;
    case ExprKind::kAssign: check_assignment(e); return;
    case ExprKind::kConditional: check_conditional(e); return;
    case ExprKind::kSequence:
      for (ExprPtr& operand : e.operands) check(*operand);
      e.resolved = e.operands.back()->resolved;
      return;
    case ExprKind::kCall: check_call(e); return;
    case ExprKind::kConstruct: check_construct(e); return;
    case ExprKind::kCast: check_cast(e); return;
    case ExprKind::kMember: check_member(e); return;
    case ExprKind::kIndex: check_index(e); return;
    case ExprKind::kInitList: diagnostics_.error(e.location, "an initialiser list is allowed only in a declaration or as the value of '='"); return;
  }
}

void Analyzer::convert(ExprPtr& e, const Type& to, const std::string& context) {
  if (is_error(e->resolved) || is_error(to)) return;
  auto conversion = implicit_conversion(e->resolved, to);
  if (!conversion) {
    diagnostics_.error(e->location, "cannot convert '" + type_name(e->resolved) + "' to '" + type_name(to) + "' in " + context);
    return;
  }
  if (conversion->truncates)
    diagnostics_.warning(e->location, "implicit truncation from '" + type_name(e->resolved) + "' to '" + type_name(to) + "'");
  if (e->resolved == to) return;
  auto cast = std::make_unique<Expr>();
  cast->kind = ExprKind::kCast;
  cast->location = e->location;
  cast->implicit = true;
  cast->resolved = to;
  cast->operands.push_back(std::move(e));
  e = std::move(cast);
}

void Analyzer::require_lvalue(const Expr& e, const char* what) {
  if (e.lvalue || is_error(e.resolved)) return;
  std::string name = e.kind == ExprKind::kName ? "'" + e.text + "'" : "this expression";
  diagnostics_.error(e.location, "cannot " + std::string(what) + " " + name + ": it is not a modifiable value");
}

void Analyzer::check_name(Expr& e) {
  if (const VariableDecl* variable = find_variable(e.text)) {
    e.variable = variable;
    e.resolved = variable->resolved;
    unsigned fixed = kQualConst | kQualUniform;
    // A global without 'static' is a uniform in FX, as in HLSL: read-only in shaders.
    bool global_plain = global_variables_.count(variable) && !(variable->qualifiers & (kQualStatic | kQualGroupShared));
    e.lvalue = !(variable->qualifiers & fixed) && !variable->resolved.is_object() && !global_plain;
    return;
  }
  if (find_functions(e.text)) diagnostics_.error(e.location, "'" + e.text + "' is a function, not a value");
  else diagnostics_.error(e.location, "unknown name '" + e.text + "'");
}

void Analyzer::check_unary(Expr& e) {
  check(*e.operands[0]);
  const Type& t = e.operands[0]->resolved;
  if (is_error(t)) return;
  std::string op = punct_spelling(e.op);
  if (!t.is_numeric()) return diagnostics_.error(e.location, "operator '" + op + "' cannot be applied to '" + type_name(t) + "'");
  if (e.op == Punct::kPlusPlus || e.op == Punct::kMinusMinus) require_lvalue(*e.operands[0], ("apply '" + op + "' to").c_str());
  if (e.op == Punct::kTilde && !t.is_integral()) return diagnostics_.error(e.location, "operator '~' needs an integer, not '" + type_name(t) + "'");
  e.resolved = e.op == Punct::kBang ? t.with_base(BaseType::kBool) : t.base == BaseType::kBool ? t.with_base(BaseType::kInt) : t;
}

void Analyzer::check_binary(Expr& e) {
  check(*e.operands[0]);
  check(*e.operands[1]);
  const Type& a = e.operands[0]->resolved;
  const Type& b = e.operands[1]->resolved;
  if (is_error(a) || is_error(b)) return;
  std::string op = punct_spelling(e.op);
  bool truncates = false;
  auto common = common_type(a, b, truncates);
  if (!common) {
    diagnostics_.error(e.location, "operator '" + op + "' cannot combine '" + type_name(a) + "' and '" + type_name(b) + "'");
    return;
  }
  if (truncates) diagnostics_.warning(e.location, "implicit truncation of vector type in '" + op + "'");
  bool logical = e.op == Punct::kAmpAmp || e.op == Punct::kPipePipe;
  if (is_bitwise(e.op) && !common->is_integral()) {
    diagnostics_.error(e.location, "operator '" + op + "' needs integers, not '" + type_name(*common) + "'");
    return;
  }
  Type operand_type = logical ? common->with_base(BaseType::kBool) : *common;
  if (!logical && !is_comparison(e.op) && operand_type.base == BaseType::kBool) operand_type.base = BaseType::kInt;
  convert(e.operands[0], operand_type, "operator '" + op + "'");
  convert(e.operands[1], operand_type, "operator '" + op + "'");
  e.resolved = logical || is_comparison(e.op) ? common->with_base(BaseType::kBool) : operand_type;
}

void Analyzer::check_assignment(Expr& e) {
  check(*e.operands[0]);
  if (e.operands[1]->kind == ExprKind::kInitList) {  // a = { ... }: the list takes the target's type
    const Type& target = e.operands[0]->resolved;
    if (is_error(target)) return;
    require_lvalue(*e.operands[0], "assign to");
    if (target.is_array() && target.array[0] == 0) return diagnostics_.error(e.location, "cannot assign to an array of unknown size");
    check_init_list(*e.operands[1], target);
    e.resolved = target;
    return;
  }
  check(*e.operands[1]);
  const Type& target = e.operands[0]->resolved;
  if (is_error(target) || is_error(e.operands[1]->resolved)) return;
  require_lvalue(*e.operands[0], "assign to");
  std::string op = punct_spelling(e.op);
  if (e.op != Punct::kAssign) {
    if (!target.is_numeric() || !e.operands[1]->resolved.is_numeric())
      return diagnostics_.error(e.location, "operator '" + op + "' needs numbers");
    if (is_bitwise(e.op) && (!target.is_integral() || !e.operands[1]->resolved.is_integral()))
      return diagnostics_.error(e.location, "operator '" + op + "' needs integers");
  }
  widen_for_assignment(e.operands[1], target);
  convert(e.operands[1], target, "assignment");
  e.resolved = target;
}

void Analyzer::widen_for_assignment(ExprPtr& value, const Type& target) {
  // ReShade checks an assignment's types the other way round (whether the target would convert to
  // the value's type), so public effects assign a float3 to a float4. It fills the components the
  // value lacks with its last one, as its casts between vector sizes do: float4 = c.rgb is c.rgbb.
  const Type from = value->resolved;
  if (!from.is_vector() || !target.is_vector() || from.rows >= target.rows) return;
  diagnostics_.warning(value->location, "'" + type_name(from) + "' assigned to '" + type_name(target) +
                                            "': its last component fills the rest, as ReShade does");
  auto widened = std::make_unique<Expr>();
  widened->kind = ExprKind::kMember;
  widened->location = value->location;
  for (int i = 0; i < target.rows; ++i) {
    widened->swizzle.push_back(std::min(i, from.rows - 1));
    widened->text += "xyzw"[widened->swizzle.back()];
  }
  widened->resolved = Type::vector(from.base, target.rows);
  widened->operands.push_back(std::move(value));
  value = std::move(widened);
}

void Analyzer::check_conditional(Expr& e) {
  for (ExprPtr& operand : e.operands) check(*operand);
  const Type& yes = e.operands[1]->resolved;
  const Type& no = e.operands[2]->resolved;
  if (is_error(e.operands[0]->resolved) || is_error(yes) || is_error(no)) return;
  if (!yes.is_numeric() || !no.is_numeric()) {
    if (yes != no) return diagnostics_.error(e.location, "the branches of '?:' have types '" + type_name(yes) + "' and '" + type_name(no) + "'");
    e.resolved = yes;
    convert(e.operands[0], Type::scalar(BaseType::kBool), "a condition");
    return;
  }
  bool truncates = false;
  auto common = common_type(yes, no, truncates);
  if (!common) return diagnostics_.error(e.location, "the branches of '?:' have types '" + type_name(yes) + "' and '" + type_name(no) + "'");
  const Type& condition = e.operands[0]->resolved;
  // A vector condition selects per component (HLSL); a scalar one selects the whole value.
  convert(e.operands[0], condition.is_vector() ? common->with_base(BaseType::kBool) : Type::scalar(BaseType::kBool), "a condition");
  convert(e.operands[1], *common, "'?:'");
  convert(e.operands[2], *common, "'?:'");
  e.resolved = *common;
}

void Analyzer::check_member(Expr& e) {
  check(*e.operands[0]);
  const Type& t = e.operands[0]->resolved;
  if (is_error(t)) return;
  if (t.base == BaseType::kStruct && !t.is_array() && t.structure) {
    for (const VariableDecl& field : t.structure->fields)
      if (field.name == e.text) {
        e.resolved = field.resolved;
        e.lvalue = e.operands[0]->lvalue;
        return;
      }
    return diagnostics_.error(e.location, "struct '" + t.structure->name + "' has no member '" + e.text + "'");
  }
  if (!t.is_numeric()) return diagnostics_.error(e.location, "'" + type_name(t) + "' has no member '" + e.text + "'");
  std::string error;
  if (!parse_swizzle(e.text, t, e.swizzle, error)) return diagnostics_.error(e.location, error);
  e.resolved = Type::vector(t.base, static_cast<int>(e.swizzle.size()));
  bool repeats = false;
  for (std::size_t i = 0; i < e.swizzle.size(); ++i)
    for (std::size_t k = i + 1; k < e.swizzle.size(); ++k) repeats = repeats || e.swizzle[i] == e.swizzle[k];
  e.lvalue = e.operands[0]->lvalue && !repeats;
}

void Analyzer::check_index(Expr& e) {
  check(*e.operands[0]);
  check(*e.operands[1]);
  const Type& t = e.operands[0]->resolved;
  if (is_error(t) || is_error(e.operands[1]->resolved)) return;
  if (!e.operands[1]->resolved.is_scalar()) return diagnostics_.error(e.operands[1]->location, "an index must be a scalar");
  convert(e.operands[1], Type::scalar(e.operands[1]->resolved.base == BaseType::kUint ? BaseType::kUint : BaseType::kInt), "an index");
  if (t.is_array()) e.resolved = t.element();
  else if (t.is_matrix()) e.resolved = Type::vector(t.base, t.columns);
  else if (t.is_vector()) e.resolved = Type::scalar(t.base);
  else return diagnostics_.error(e.location, "'" + type_name(t) + "' cannot be indexed");
  e.lvalue = e.operands[0]->lvalue;
}

void Analyzer::check_construct(Expr& e) {
  Type target = resolve_type(e.type, e.location);
  if (is_error(target)) return;
  int components = 0;
  bool failed = false;
  for (ExprPtr& argument : e.operands) {
    check(*argument);
    if (is_error(argument->resolved)) failed = true;
    else if (!argument->resolved.is_numeric()) {
      diagnostics_.error(argument->location, "a constructor argument must be a number, not '" + type_name(argument->resolved) + "'");
      failed = true;
    } else {
      components += argument->resolved.components();
    }
  }
  if (failed) return;
  bool splat = e.operands.size() == 1 && components == 1;
  if (!target.is_numeric() || (components != target.components() && !splat)) {
    diagnostics_.error(e.location, "'" + type_name(target) + "' constructor needs " + std::to_string(target.components()) +
                                       " components, not " + std::to_string(components));
    return;
  }
  e.resolved = target;
}

void Analyzer::check_cast(Expr& e) {
  check(*e.operands[0]);
  Type target = resolve_type(e.type, e.location);
  const Type& from = e.operands[0]->resolved;
  if (is_error(target) || is_error(from)) return;
  if (!explicit_conversion(from, target))
    return diagnostics_.error(e.location, "cannot cast '" + type_name(from) + "' to '" + type_name(target) + "'");
  e.resolved = target;
}

}  // namespace pfx::fx
