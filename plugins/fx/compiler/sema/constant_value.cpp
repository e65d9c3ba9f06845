#include "constant_value.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pfx::fx {
namespace {

using Value = std::optional<ConstantValue>;

Value scalar(double v) {
  ConstantValue c;
  c.components.push_back(v);
  return c;
}

bool integral(const Expr& e) { return e.resolved.is_integral(); }

// An integer as HLSL's 32-bit integers hold it: modulo 2^32, into [0, 2^32) for uint and
// [-2^31, 2^31) for int (0u - 1u is 0xFFFFFFFF, 0x7FFFFFFF + 1 is INT_MIN). Other types as they are.
double wrap32(double v, BaseType base) {
  if ((base != BaseType::kInt && base != BaseType::kUint) || !std::isfinite(v)) return v;
  const std::int64_t whole = static_cast<std::int64_t>(std::fmod(v, 4294967296.0));
  const std::uint32_t bits = static_cast<std::uint32_t>(whole);
  return base == BaseType::kUint ? static_cast<double>(bits) : static_cast<double>(static_cast<std::int32_t>(bits));
}

// x op y on 32-bit integers (both exact in a double), wrapping as the GPU does; shifts use the
// low five bits of the count, as HLSL's do. Division and remainder truncate toward zero.
std::optional<double> integer_op(Punct op, double x, double y, BaseType base) {
  const std::int64_t a = static_cast<std::int64_t>(x), b = static_cast<std::int64_t>(y);
  const std::uint64_t ua = static_cast<std::uint64_t>(a), ub = static_cast<std::uint64_t>(b);
  std::uint64_t r = 0;
  switch (op) {
    case Punct::kPlus: r = ua + ub; break;
    case Punct::kMinus: r = ua - ub; break;
    case Punct::kStar: r = ua * ub; break;
    case Punct::kShiftLeft: r = ua << (b & 31); break;
    case Punct::kShiftRight:
      r = base == BaseType::kUint ? (ua & 0xFFFFFFFFu) >> (b & 31) : static_cast<std::uint64_t>(a >> (b & 31));
      break;
    case Punct::kAmp: r = ua & ub; break;
    case Punct::kPipe: r = ua | ub; break;
    case Punct::kCaret: r = ua ^ ub; break;
    default: return std::nullopt;
  }
  return wrap32(static_cast<double>(static_cast<std::int64_t>(r & 0xFFFFFFFFu)), base);
}

Value evaluate(const Expr& e, int depth);

// Elementwise a op b; a one-component side is splat over the other.
Value combine(const Expr& e, const ConstantValue& a, const ConstantValue& b) {
  std::size_t n = std::max(a.components.size(), b.components.size());
  if (a.components.empty() || b.components.empty()) return std::nullopt;
  if (a.components.size() != n && a.components.size() != 1) return std::nullopt;
  if (b.components.size() != n && b.components.size() != 1) return std::nullopt;
  bool integers = integral(e) || (integral(*e.operands[0]) && integral(*e.operands[1]));
  // The result's integer type, where the analysis gave one (an unchecked annotation has none).
  const BaseType wraps = integral(e) ? e.resolved.base : BaseType::kFloat;
  ConstantValue out;
  for (std::size_t i = 0; i < n; ++i) {
    double x = a.components[a.components.size() == 1 ? 0 : i];
    double y = b.components[b.components.size() == 1 ? 0 : i];
    if (wraps != BaseType::kFloat) {
      if (std::optional<double> r = integer_op(e.op, x, y, wraps)) {
        out.components.push_back(*r);
        continue;
      }
    }
    double r = 0;
    switch (e.op) {
      case Punct::kPlus: r = x + y; break;
      case Punct::kMinus: r = x - y; break;
      case Punct::kStar: r = x * y; break;
      case Punct::kSlash:
        if (integers && y == 0) return std::nullopt;
        r = wrap32(integers ? std::trunc(x / y) : x / y, wraps);  // INT_MIN / -1 wraps to INT_MIN
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

// A float as HLSL converts it to an int or uint (ftoi, ftou): toward zero, saturated at the type's
// range, NaN to 0.
double float_to_integer(double v, BaseType base) {
  if (std::isnan(v)) return 0;
  const double low = base == BaseType::kUint ? 0.0 : -2147483648.0, high = base == BaseType::kUint ? 4294967295.0 : 2147483647.0;
  return std::min(high, std::max(low, std::trunc(v)));
}

// The components of a conversion to `to` (splat, truncation, integer rounding toward zero; from
// integers, an integer type wraps at 32 bits: uint(-2) is 0xFFFFFFFE; from floats, it saturates:
// uint(-2.0) is 0).
Value convert(const ConstantValue& v, const Type& to, bool from_integers) {
  if (v.is_string) return v;
  ConstantValue out = v;
  int wanted = to.is_numeric() ? to.components() : static_cast<int>(v.components.size());
  if (to.is_numeric() && !to.is_array()) {
    if (out.components.size() == 1 && wanted > 1) out.components.assign(static_cast<std::size_t>(wanted), out.components[0]);
    else if (static_cast<int>(out.components.size()) > wanted) out.components.resize(static_cast<std::size_t>(wanted));
  }
  if (to.base == BaseType::kInt || to.base == BaseType::kUint)
    for (double& c : out.components) c = from_integers ? wrap32(std::trunc(c), to.base) : float_to_integer(c, to.base);
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
      const BaseType wraps = integral(e) ? e.resolved.base : BaseType::kFloat;
      for (double& c : v->components) {
        if (e.op == Punct::kMinus) c = wrap32(-c, wraps);
        else if (e.op == Punct::kBang) c = c == 0 ? 1 : 0;
        else if (e.op == Punct::kTilde) c = wrap32(static_cast<double>(~static_cast<long long>(c)), wraps);
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
      bool from_integers = true;
      for (const ExprPtr& operand : e.operands) from_integers = from_integers && integral(*operand);
      return convert(*v, to, from_integers);
    }
    case ExprKind::kInitList: return evaluate_list(e, depth);
    case ExprKind::kCast: {
      Value v = evaluate(*e.operands[0], depth + 1);
      if (!v) return std::nullopt;
      return e.resolved.is_numeric() ? convert(*v, e.resolved, integral(*e.operands[0])) : v;
    }
    case ExprKind::kName: {
      if (!e.variable || !(e.variable->qualifiers & kQualConst) || !e.variable->initializer) return std::nullopt;
      // As the variable holds it: `static const int2 Size = 256;` is (256, 256).
      Value v = evaluate(*e.variable->initializer, depth + 1);
      if (v && e.variable->resolved.is_numeric())
        return convert(*v, e.variable->resolved, integral(*e.variable->initializer));
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
