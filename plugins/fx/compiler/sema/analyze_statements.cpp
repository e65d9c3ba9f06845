// Statements: scopes, conditions, loops, switch labels, jumps and return values.
#include "analyzer.hpp"
#include "constant_eval.hpp"

namespace pfx::fx {

void Analyzer::check_condition(ExprPtr& condition) {
  check(*condition);
  if (is_error(condition->resolved)) return;
  if (!condition->resolved.is_scalar()) {
    if (condition->resolved.is_numeric()) {
      diagnostics_.warning(condition->location, "condition of type '" + type_name(condition->resolved) +
                                                    "' uses only its first component");
    } else {
      diagnostics_.error(condition->location, "condition of type '" + type_name(condition->resolved) + "' is not a number");
      return;
    }
  }
  convert(condition, Type::scalar(BaseType::kBool), "a condition");
}

void Analyzer::check_statement(Stmt& s) {
  if (diagnostics_.too_many_errors()) return;
  switch (s.kind) {
    case StmtKind::kEmpty: return;
    case StmtKind::kExpression: check(*s.expression); return;
    case StmtKind::kDeclaration: declare_variables(s.variables, false); return;
    case StmtKind::kBlock:
      push_scope();
      for (StmtPtr& inner : s.statements) check_statement(*inner);
      pop_scope();
      return;
    case StmtKind::kIf:
      check_condition(s.expression);
      check_statement(*s.body);
      if (s.else_body) check_statement(*s.else_body);
      return;
    case StmtKind::kFor:
      push_scope();  // the loop variable lives in the loop
      if (s.init) check_statement(*s.init);
      if (s.expression) check_condition(s.expression);
      if (s.increment) check(*s.increment);
      ++loop_depth_;
      check_statement(*s.body);
      --loop_depth_;
      pop_scope();
      return;
    case StmtKind::kWhile:
    case StmtKind::kDoWhile:
      check_condition(s.expression);
      ++loop_depth_;
      check_statement(*s.body);
      --loop_depth_;
      return;
    case StmtKind::kSwitch: check_switch(s); return;
    case StmtKind::kBreak:
      if (loop_depth_ == 0 && switch_depth_ == 0) diagnostics_.error(s.location, "'break' outside a loop or switch");
      return;
    case StmtKind::kContinue:
      if (loop_depth_ == 0) diagnostics_.error(s.location, "'continue' outside a loop");
      return;
    case StmtKind::kDiscard: return;
    case StmtKind::kReturn: {
      Type expected = current_function_ ? current_function_->resolved : Type{};
      if (is_error(expected)) return;
      if (!s.expression) {
        if (!expected.is_void() && !is_error(expected)) diagnostics_.error(s.location, "'return' needs a value of type '" + type_name(expected) + "'");
        return;
      }
      check(*s.expression);
      if (expected.is_void()) {
        if (!is_error(s.expression->resolved) && !s.expression->resolved.is_void())
          diagnostics_.error(s.location, "a void function cannot return a value");
        return;
      }
      convert(s.expression, expected, "the return value");
      return;
    }
  }
}

void Analyzer::check_switch(Stmt& s) {
  check(*s.expression);
  if (!is_error(s.expression->resolved) && !(s.expression->resolved.is_scalar() && s.expression->resolved.is_integral()))
    diagnostics_.error(s.expression->location, "switch value must be an integer scalar, not '" +
                                                   type_name(s.expression->resolved) + "'");
  std::set<long long> seen;
  bool has_default = false;
  ++switch_depth_;
  for (SwitchCase& group : s.cases) {
    for (ExprPtr& label : group.labels) {
      check(*label);
      auto value = evaluate_integer_constant(*label);
      if (!value) diagnostics_.error(label->location, "case label is not an integer constant");
      else if (!seen.insert(*value).second) diagnostics_.error(label->location, "duplicate case " + std::to_string(*value));
    }
    if (group.has_default && has_default) diagnostics_.error(group.location, "more than one 'default'");
    has_default = has_default || group.has_default;
    push_scope();
    for (StmtPtr& inner : group.body) check_statement(*inner);
    pop_scope();
  }
  --switch_depth_;
}

}  // namespace pfx::fx
