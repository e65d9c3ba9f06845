#include "constant_value.hpp"

#include <cmath>

namespace pfx::fx {
namespace {

using Value = std::optional<ConstantValue>;

Value scalar(double v) {
  ConstantValue c;
  c.components.push_back(v);
  return c;
}

bool integral(const Expr& e) { return e.resolved.is_integral(); }

Value evaluate(const Expr& e, int depth);

// Elementwise a op b; a one-component side is splat over the other.
Value combine(const Expr& e, const ConstantValue& a, const ConstantValue& b) {
  std::size_t n = std::max(a.components.size(), b.components.size());
  if (a.components.empty() || b.components.empty()) return std::nullopt;
  if (a.components.size() != n && a.components.size() != 1) return std::nullopt;
  if (b.components.size() != n && b.components.size() != 1) return std::nullopt;
  bool integers = integral(e) || (integral(*e.operands[0]) && integral(*e.operands[1]));
  ConstantValue out;
  for (std::size_t i = 0; i < n; ++i) {
    double x = a.components[a.components.size() == 1 ? 0 : i];
    double y = b.components[b.components.size() == 1 ? 0 : i];
    double r = 0;
    switch (e.op) {
      case Punct::kPlus: r = x + y; break;
      case Punct::kMinus: r = x - y; break;
      case Punct::kStar: r = x * y; break;
      case Punct::kSlash:
        if (integers && y == 0) return std::nullopt;
        r = integers ? std::trunc(x / y) : x / y;
        break;
      case Punct::kPercent:
        if (y == 0) return std::nullopt;
        r = std::fmod(x, y);
        break;
      case Punct::kLess: r = x < y; break;
      case Punct::kGreater: r = x > y; break;
      case Punct::kLessEqual: r = x <= y; break;
      case Punct::kGreaterEqual: r = x >= y; break;
      case Punct::kEqualEqual: r = x == y; break;
      case Punct::kBangEqual: r = x != y; break;
      case Punct::kAmpAmp: r = x != 0 && y != 0; break;
      case Punct::kPipePipe: r = x != 0 || y != 0; break;
      case Punct::kShiftLeft: r = y >= 0 && y < 32 ? x * std::pow(2.0, y) : 0; break;
      case Punct::kShiftRight: r = y >= 0 && y < 32 ? std::floor(x / std::pow(2.0, y)) : 0; break;
      case Punct::kAmp: r = static_cast<double>(static_cast<long long>(x) & static_cast<long long>(y)); break;
      case Punct::kPipe: r = static_cast<double>(static_cast<long long>(x) | static_cast<long long>(y)); break;
      case Punct::kCaret: r = static_cast<double>(static_cast<long long>(x) ^ static_cast<long long>(y)); break;
      default: return std::nullopt;
    }
    out.components.push_back(r);
  }
  return out;
}

// The components of a conversion to `to` (splat, truncation, integer rounding toward zero).
Value convert(const ConstantValue& v, const Type& to) {
  if (v.is_string) return v;
  ConstantValue out = v;
  int wanted = to.is_numeric() ? to.components() : static_cast<int>(v.components.size());
  if (to.is_numeric() && !to.is_array()) {
    if (out.components.size() == 1 && wanted > 1) out.components.assign(static_cast<std::size_t>(wanted), out.components[0]);
    else if (static_cast<int>(out.components.size()) > wanted) out.components.resize(static_cast<std::size_t>(wanted));
  }
  if (to.base == BaseType::kInt || to.base == BaseType::kUint)
    for (double& c : out.components) c = std::trunc(c);
  if (to.base == BaseType::kBool)
    for (double& c : out.components) c = c != 0 ? 1 : 0;
  return out;
}

Value evaluate_list(const Expr& e, int depth) {
  ConstantValue out;
  for (const ExprPtr& operand : e.operands) {
    Value part = evaluate(*operand, depth + 1);
    if (!part || part->is_string) return std::nullopt;
    out.components.insert(out.components.end(), part->components.begin(), part->components.end());
  }
  return out;
}

Value evaluate(const Expr& e, int depth) {
  if (depth > 64) return std::nullopt;
  switch (e.kind) {
    case ExprKind::kInt: return scalar(static_cast<double>(e.number.kind == NumberLiteral::Kind::kUint
                                                                ? static_cast<double>(static_cast<std::uint32_t>(e.number.integer))
                                                                : static_cast<double>(static_cast<std::int32_t>(e.number.integer))));
    case ExprKind::kFloat: return scalar(e.number.real);
    case ExprKind::kBool: return scalar(e.boolean ? 1.0 : 0.0);
    case ExprKind::kString: {
      ConstantValue c;
      c.is_string = true;
      c.text = e.text;
      return c;
    }
    case ExprKind::kUnary: {
      Value v = evaluate(*e.operands[0], depth + 1);
      if (!v || v->is_string) return std::nullopt;
      for (double& c : v->components) {
        if (e.op == Punct::kMinus) c = -c;
        else if (e.op == Punct::kBang) c = c == 0 ? 1 : 0;
        else if (e.op == Punct::kTilde) c = static_cast<double>(~static_cast<long long>(c));
        else if (e.op != Punct::kPlus) return std::nullopt;
      }
      return v;
    }
    case ExprKind::kBinary: {
      Value a = evaluate(*e.operands[0], depth + 1);
      Value b = evaluate(*e.operands[1], depth + 1);
      if (!a || !b || a->is_string || b->is_string) return std::nullopt;
      return combine(e, *a, *b);
    }
    case ExprKind::kConditional: {
      Value c = evaluate(*e.operands[0], depth + 1);
      if (!c || c->components.size() != 1) return std::nullopt;
      return evaluate(*e.operands[c->components[0] != 0 ? 1 : 2], depth + 1);
    }
    case ExprKind::kConstruct: {
      Value v = evaluate_list(e, depth);
      if (!v) return std::nullopt;
      Type to = e.resolved.is_numeric() ? e.resolved : Type::vector(e.type.base, e.type.rows);
      if (e.type.shape == Shape::kMatrix && !e.resolved.is_numeric()) to = Type::matrix(e.type.base, e.type.rows, e.type.columns);
      return convert(*v, to);
    }
    case ExprKind::kInitList: return evaluate_list(e, depth);
    case ExprKind::kCast: {
      Value v = evaluate(*e.operands[0], depth + 1);
      if (!v) return std::nullopt;
      return e.resolved.is_numeric() ? convert(*v, e.resolved) : v;
    }
    case ExprKind::kName: {
      if (!e.variable || !(e.variable->qualifiers & kQualConst) || !e.variable->initializer) return std::nullopt;
      // As the variable holds it: `static const int2 Size = 256;` is (256, 256).
      Value v = evaluate(*e.variable->initializer, depth + 1);
      if (v && e.variable->resolved.is_numeric()) return convert(*v, e.variable->resolved);
      return v;
    }
    case ExprKind::kMember: {
      Value v = evaluate(*e.operands[0], depth + 1);
      if (!v || e.swizzle.empty() || v->is_string) return std::nullopt;
      const Type& from = e.operands[0]->resolved;
      ConstantValue out;
      for (int index : e.swizzle) {
        int flat = from.is_matrix() ? (index / 4) * from.columns + index % 4 : index;
        if (flat < 0 || static_cast<std::size_t>(flat) >= v->components.size()) return std::nullopt;
        out.components.push_back(v->components[static_cast<std::size_t>(flat)]);
      }
      return out;
    }
    case ExprKind::kSequence: return evaluate(*e.operands.back(), depth + 1);
    default: return std::nullopt;
  }
}

}  // namespace

std::optional<ConstantValue> evaluate_constant(const Expr& expression) { return evaluate(expression, 0); }

}  // namespace pfx::fx
