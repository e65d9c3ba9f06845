#include "constant_eval.hpp"

#include <cmath>

namespace pfx::fx {
namespace {

std::optional<double> evaluate(const Expr& e, int depth);

std::optional<double> binary(const Expr& e, int depth) {
  auto a = evaluate(*e.operands[0], depth + 1);
  auto b = evaluate(*e.operands[1], depth + 1);
  if (!a || !b) return std::nullopt;
  bool integers = e.resolved.is_integral();
  switch (e.op) {
    case Punct::kPlus: return *a + *b;
    case Punct::kMinus: return *a - *b;
    case Punct::kStar: return *a * *b;
    case Punct::kSlash:
      if (*b == 0) return std::nullopt;
      return integers ? std::trunc(*a / *b) : *a / *b;
    case Punct::kPercent:
      if (*b == 0) return std::nullopt;
      return std::fmod(*a, *b);
    case Punct::kShiftLeft: return *b >= 0 && *b < 31 ? std::optional<double>(*a * std::pow(2.0, *b)) : std::nullopt;
    case Punct::kShiftRight: return *b >= 0 && *b < 31 ? std::optional<double>(std::floor(*a / std::pow(2.0, *b))) : std::nullopt;
    default: return std::nullopt;
  }
}

std::optional<double> evaluate(const Expr& e, int depth) {
  if (depth > 64) return std::nullopt;  // static const chains deeper than this are not sizes
  switch (e.kind) {
    case ExprKind::kInt: return static_cast<double>(e.number.integer);
    case ExprKind::kFloat: return e.number.real;
    case ExprKind::kBool: return e.boolean ? 1.0 : 0.0;
    case ExprKind::kUnary:
      if (e.op == Punct::kMinus) {
        auto v = evaluate(*e.operands[0], depth + 1);
        return v ? std::optional<double>(-*v) : std::nullopt;
      }
      if (e.op == Punct::kPlus) return evaluate(*e.operands[0], depth + 1);
      return std::nullopt;
    case ExprKind::kBinary: return binary(e, depth);
    case ExprKind::kCast: {
      auto v = evaluate(*e.operands[0], depth + 1);
      if (v && e.resolved.is_integral()) return std::trunc(*v);
      return v;
    }
    case ExprKind::kName:
      if (e.variable && (e.variable->qualifiers & kQualConst) && e.variable->initializer &&
          e.variable->initializer->kind != ExprKind::kInitList)
        return evaluate(*e.variable->initializer, depth + 1);
      return std::nullopt;
    default: return std::nullopt;
  }
}

}  // namespace

std::optional<long long> evaluate_integer_constant(const Expr& expression) {
  auto value = evaluate(expression, 0);
  if (!value || !std::isfinite(*value) || std::fabs(*value) > 9.0e15) return std::nullopt;
  return static_cast<long long>(*value);
}

}  // namespace pfx::fx
