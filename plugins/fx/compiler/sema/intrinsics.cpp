#include "intrinsics.hpp"

#include "conversions.hpp"

namespace pfx::fx {
namespace {

using Rule = IntrinsicRule;

BaseType floating(BaseType base) { return base == BaseType::kHalf || base == BaseType::kDouble ? base : BaseType::kFloat; }

// The common type of all arguments (numeric only).
bool widest(const std::vector<Type>& arguments, Type& result, std::string& error) {
  result = arguments[0];
  for (const Type& a : arguments) {
    bool truncates = false;
    auto common = a.is_numeric() && result.is_numeric() ? common_type(result, a, truncates) : std::nullopt;
    if (!common) {
      error = "arguments of types '" + type_name(result) + "' and '" + type_name(a) + "' do not combine";
      return false;
    }
    result = *common;
  }
  return true;
}

Type mul_result(const Type& a, const Type& b, bool& ok) {
  ok = true;
  BaseType base = base_rank(a.base) >= base_rank(b.base) ? a.base : b.base;
  if (a.is_scalar()) return b.with_base(base);
  if (b.is_scalar()) return a.with_base(base);
  if (a.is_vector() && b.is_vector()) return Type::scalar(base);
  if (a.is_vector() && b.is_matrix()) return ok = a.rows == b.rows, Type::vector(base, b.columns);
  if (a.is_matrix() && b.is_vector()) return ok = a.columns == b.rows, Type::vector(base, a.rows);
  ok = a.columns == b.rows;
  return Type::matrix(base, a.rows, b.columns);
}

}  // namespace

bool type_intrinsic(const std::string& name, const std::vector<Type>& arguments, IntrinsicTyping& typing,
                    std::string& error) {
  const IntrinsicInfo* found = find_intrinsic(name);
  if (!found) return error = "unknown intrinsic '" + name + "'", false;
  const IntrinsicInfo& entry = *found;
  typing.id = entry.id;
  int count = static_cast<int>(arguments.size());
  if (count < entry.min_arguments || count > entry.max_arguments) {
    error = "'" + name + "' takes " + std::to_string(entry.min_arguments) +
            (entry.max_arguments != entry.min_arguments ? " to " + std::to_string(entry.max_arguments) : "") +
            " argument(s), not " + std::to_string(count);
    return false;
  }
  typing.parameters.assign(arguments.size(), Type{});
  typing.writes.assign(arguments.size(), false);
  bool object_first = entry.rule == Rule::kSample || entry.rule == Rule::kSize || entry.rule == Rule::kGather ||
                      entry.rule == Rule::kStore || (entry.rule == Rule::kAtomic && !arguments.empty() && arguments[0].is_object());
  if (object_first && (arguments.empty() || !arguments[0].is_object() || arguments[0].base == BaseType::kTexture))
    return error = "'" + name + "' needs a sampler or storage as its first argument", false;
  for (std::size_t i = object_first ? 1 : 0; i < arguments.size(); ++i)
    if (!arguments[i].is_numeric()) return error = "argument " + std::to_string(i + 1) + " of '" + name + "' is not a number", false;
  Type w;
  switch (entry.rule) {
    case Rule::kFloatWise:
    case Rule::kNumberWise:
      if (!widest(arguments, w, error)) return false;
      if (entry.rule == Rule::kFloatWise || w.base == BaseType::kBool) w.base = entry.rule == Rule::kFloatWise ? floating(w.base) : BaseType::kInt;
      typing.result = w;
      typing.parameters.assign(arguments.size(), w);
      return true;
    case Rule::kBoolWise: typing.result = arguments[0].with_base(BaseType::kBool); return true;
    case Rule::kIntWise: typing.result = arguments[0].with_base(BaseType::kInt); return true;
    case Rule::kUintWise: typing.result = arguments[0].with_base(BaseType::kUint); return true;
    case Rule::kAsFloat: typing.result = arguments[0].with_base(BaseType::kFloat); return true;
    case Rule::kAsInt: typing.result = arguments[0].with_base(BaseType::kInt); return true;
    case Rule::kAsUint: typing.result = arguments[0].with_base(BaseType::kUint); return true;
    case Rule::kHalfToFloat: typing.result = arguments[0].with_base(BaseType::kFloat); return true;
    case Rule::kFloatToHalf: typing.result = arguments[0].with_base(BaseType::kUint); return true;
    case Rule::kScalarFloat:
      if (!widest(arguments, w, error)) return false;
      typing.result = Type::scalar(floating(w.base));
      if (entry.id != Intrinsic::kDeterminant) typing.parameters.assign(arguments.size(), w.with_base(floating(w.base)));
      return true;
    case Rule::kCross:
      typing.result = Type::vector(BaseType::kFloat, 3);
      typing.parameters.assign(2, typing.result);
      return true;
    case Rule::kTranspose:
      typing.result = arguments[0];
      std::swap(typing.result.rows, typing.result.columns);
      return arguments[0].is_matrix() ? true : (error = "'transpose' needs a matrix", false);
    case Rule::kMul: {
      bool ok = true;
      typing.result = mul_result(arguments[0], arguments[1], ok);
      if (!ok) error = "'mul' of '" + type_name(arguments[0]) + "' and '" + type_name(arguments[1]) + "': sizes do not match";
      return ok;
    }
    case Rule::kAllAny: typing.result = Type::scalar(BaseType::kBool); return true;
    case Rule::kSinCos:
      typing.result = Type{};
      typing.writes = {false, true, true};
      return true;
    case Rule::kOutSecond:
      typing.result = arguments[0].with_base(floating(arguments[0].base));
      typing.writes = {false, true};
      return true;
    case Rule::kVoid: typing.result = Type{}; return true;
    case Rule::kSample: typing.result = Type::vector(arguments[0].element_base, arguments[0].element_rows); return true;
    case Rule::kSize: typing.result = Type::vector(BaseType::kInt, arguments[0].dimension); return true;
    case Rule::kGather: typing.result = Type::vector(arguments[0].element_base, 4); return true;
    case Rule::kStore: typing.result = Type{}; return true;
    case Rule::kAtomic:
      typing.result = Type::scalar(arguments[0].is_object() ? arguments[0].element_base : arguments[0].base);
      if (!arguments[0].is_object()) typing.writes[0] = true;
      return true;
  }
  return true;
}

}  // namespace pfx::fx
