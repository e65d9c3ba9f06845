// Calls: overload resolution over user functions (cheapest implicit conversions win, a tie is
// ambiguous), then intrinsics; initialiser lists.
#include <limits>

#include "analyzer.hpp"
#include "conversions.hpp"
#include "intrinsics.hpp"

namespace pfx::fx {
namespace {

std::string argument_list(const std::vector<ExprPtr>& arguments) {
  std::string text = "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) text += (i ? ", " : "") + type_name(arguments[i]->resolved);
  return text + ")";
}

// The cost of calling `f` with `arguments`, or -1 when it cannot take them.
int call_cost(const FunctionDecl& f, const std::vector<ExprPtr>& arguments) {
  if (arguments.size() > f.parameters.size()) return -1;
  for (std::size_t i = arguments.size(); i < f.parameters.size(); ++i)
    if (!f.parameters[i].initializer) return -1;
  int cost = 0;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const VariableDecl& p = f.parameters[i];
    auto in = implicit_conversion(arguments[i]->resolved, p.resolved);
    if (!in) return -1;
    if (p.qualifiers & kQualOut) {  // the value also travels back
      auto back = implicit_conversion(p.resolved, arguments[i]->resolved);
      if (!back) return -1;
      cost += back->cost;
    }
    cost += in->cost;
  }
  return cost;
}

}  // namespace

void Analyzer::check_call(Expr& e) {
  bool failed = false;
  for (ExprPtr& argument : e.operands) {
    check(*argument);
    failed = failed || is_error(argument->resolved);
  }
  if (failed) return;
  std::string qualified;
  const std::vector<FunctionDecl*>* overloads = find_functions(e.text, &qualified);
  if (overloads && check_user_call(e, *overloads, qualified)) return;
  if (find_intrinsic(e.text)) return check_intrinsic_call(e);
  if (overloads)
    return diagnostics_.error(e.location, "no overload of '" + e.text + "' takes " + argument_list(e.operands));
  if (find_variable(e.text)) return diagnostics_.error(e.location, "'" + e.text + "' is not a function");
  diagnostics_.error(e.location, "unknown function '" + e.text + "'");
}

bool Analyzer::check_user_call(Expr& e, const std::vector<FunctionDecl*>& overloads, const std::string& qualified) {
  int best_cost = std::numeric_limits<int>::max();
  FunctionDecl* best = nullptr;
  bool ambiguous = false;
  for (FunctionDecl* candidate : overloads) {
    int cost = call_cost(*candidate, e.operands);
    if (cost < 0) continue;
    if (cost < best_cost) best_cost = cost, best = candidate, ambiguous = false;
    else if (cost == best_cost) ambiguous = true;
  }
  if (!best) return false;
  if (ambiguous) {
    diagnostics_.error(e.location, "ambiguous call to '" + qualified + "' with " + argument_list(e.operands));
    return true;
  }
  for (std::size_t i = 0; i < e.operands.size(); ++i) {
    const VariableDecl& p = best->parameters[i];
    if (p.qualifiers & kQualOut) require_lvalue(*e.operands[i], "pass as an out parameter");
    else convert(e.operands[i], p.resolved, "argument " + std::to_string(i + 1) + " of '" + e.text + "'");
  }
  e.function = best;
  e.resolved = best->resolved;
  if (current_function_) calls_[current_function_].push_back({best, e.location});
  return true;
}

void Analyzer::check_intrinsic_call(Expr& e) {
  std::vector<Type> types;
  for (const ExprPtr& argument : e.operands) types.push_back(argument->resolved);
  IntrinsicTyping typing;
  std::string error;
  if (!type_intrinsic(e.text, types, typing, error)) return diagnostics_.error(e.location, error);
  for (std::size_t i = 0; i < e.operands.size(); ++i) {
    if (typing.writes[i]) require_lvalue(*e.operands[i], ("pass to '" + e.text + "' as an out argument").c_str());
    else if (!typing.parameters[i].is_void()) convert(e.operands[i], typing.parameters[i], "argument " + std::to_string(i + 1) + " of '" + e.text + "'");
  }
  e.intrinsic = typing.id;
  e.resolved = typing.result;
}

namespace {

// Scalars in one value of `type` (structs: all fields; arrays: every element).
long long scalar_count(const Type& type) {
  long long count = 1;
  for (int size : type.array) count *= size;
  if (type.base == BaseType::kStruct && type.structure) {
    long long fields = 0;
    for (const VariableDecl& field : type.structure->fields) fields += scalar_count(field.resolved);
    return count * fields;
  }
  return count * type.components();
}

}  // namespace

void Analyzer::check_init_list(Expr& list, const Type& target) {
  // HLSL flattens braces: { {1, 2}, {3, 4} } and { 1, 2, 3, 4 } both fill a float2[2].
  long long leaves = 0;
  bool failed = false;
  std::vector<Expr*> pending{&list};
  while (!pending.empty()) {
    Expr* e = pending.back();
    pending.pop_back();
    for (ExprPtr& operand : e->operands) {
      if (operand->kind == ExprKind::kInitList) {
        pending.push_back(operand.get());
        continue;
      }
      check(*operand);
      if (is_error(operand->resolved)) failed = true;
      else if (operand->resolved.is_numeric()) leaves += operand->resolved.components();
      else leaves += scalar_count(operand->resolved);
    }
  }
  if (failed) return;
  Type resolved = target;
  if (resolved.is_array() && resolved.array[0] == 0) {
    Type one = resolved.element();
    long long per = scalar_count(one);
    if (per > 0 && leaves % per == 0 && leaves > 0) resolved.array[0] = static_cast<int>(leaves / per);
  }
  long long expected = scalar_count(resolved);
  if (leaves != expected)
    diagnostics_.error(list.location, "initialiser list has " + std::to_string(leaves) + " values; '" + type_name(resolved) +
                                          "' needs " + std::to_string(expected));
  list.resolved = resolved;
}

}  // namespace pfx::fx
