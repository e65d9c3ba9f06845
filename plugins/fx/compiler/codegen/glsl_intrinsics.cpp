// HLSL's and ReShade's intrinsics in GLSL. Each keeps its HLSL meaning: fmod truncates, frac is
// x - floor(x), sign returns int, round rounds half to even, mul's operands swap (the matrix
// storage of glsl_generator.hpp), and every texture access flips v between FX's top-left origin
// and GL's bottom-left one.
#include <algorithm>
#include <map>

#include "glsl_writer.hpp"

#include "../sema/constant_value.hpp"

namespace pfx::fx {
namespace {

// Intrinsics that are one GLSL function of the same arguments.
const std::map<std::string, std::string>& renamed() {
  static const std::map<std::string, std::string> names = {
      {"abs", "abs"},         {"acos", "acos"},       {"asin", "asin"},         {"atan", "atan"},
      {"ceil", "ceil"},       {"clamp", "clamp"},     {"cos", "cos"},           {"cosh", "cosh"},
      {"cross", "cross"},     {"degrees", "degrees"}, {"determinant", "determinant"}, {"distance", "distance"},
      {"dot", "dot"},         {"exp", "exp"},         {"exp2", "exp2"},         {"floor", "floor"},
      {"fwidth", "fwidth"},   {"isinf", "isinf"},     {"isnan", "isnan"},
      {"length", "length"},   {"log", "log"},         {"log2", "log2"},         {"max", "max"},
      {"min", "min"},         {"normalize", "normalize"}, {"pow", "pow"},       {"radians", "radians"},
      {"reflect", "reflect"}, {"sin", "sin"},           {"sinh", "sinh"},
      {"smoothstep", "smoothstep"}, {"sqrt", "sqrt"}, {"step", "step"},         {"tan", "tan"},
      {"tanh", "tanh"},       {"transpose", "transpose"}, {"trunc", "trunc"},   {"frac", "fract"},
      {"lerp", "mix"},        {"rsqrt", "inversesqrt"}, {"atan2", "atan"},      {"round", "roundEven"},
      {"ddx", "dFdx"},        {"ddx_coarse", "dFdxCoarse"}, {"ddx_fine", "dFdxFine"},
      {"reversebits", "bitfieldReverse"}, {"faceforward", "faceforward"}, {"modf", "modf"}};
  return names;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
  return text;
}

}  // namespace

std::string GlslWriter::intrinsic(const Expr& e) {
  const std::string& name = e.intrinsic;
  std::vector<std::string> a;
  for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
  auto type_of = [&](std::size_t i) -> const Type& { return e.operands[i]->resolved; };
  auto it = renamed().find(name);
  if (it != renamed().end()) return it->second + "(" + joined(a) + ")";

  if (name.compare(0, 3, "tex") == 0 && name.size() > 4 && (name[3] == '1' || name[3] == '2' || name[3] == '3'))
    return texture_call(e, name);
  if (name.compare(0, 6, "atomic") == 0) {
    static const std::map<std::string, std::string> atomics = {
        {"atomicAdd", "Add"}, {"atomicAnd", "And"}, {"atomicOr", "Or"}, {"atomicXor", "Xor"},
        {"atomicMin", "Min"}, {"atomicMax", "Max"}, {"atomicExchange", "Exchange"}, {"atomicCompareExchange", "CompSwap"}};
    const std::string& op = atomics.at(name);
    if (type_of(0).base == BaseType::kStorage) {
      helpers.insert("flip");
      std::string coordinate = type_of(0).dimension == 1 ? "int(" + a[1] + ")"
                                                           : "pfx_flip_texel(ivec" + std::to_string(type_of(0).dimension) + "(" + a[1] +
                                                                 "), imageSize(" + a[0] + ").y)";
      std::vector<std::string> rest(a.begin() + 2, a.end());
      return "imageAtomic" + op + "(" + a[0] + ", " + coordinate + ", " + joined(rest) + ")";
    }
    return "atomic" + op + "(" + joined(a) + ")";
  }
  if (name == "ddy" || name == "ddy_coarse" || name == "ddy_fine") {
    // FX's y grows downwards, GL's upwards.
    std::string f = name == "ddy" ? "dFdy" : name == "ddy_coarse" ? "dFdyCoarse" : "dFdyFine";
    return "(-" + f + "(" + a[0] + "))";
  }
  // HLSL's ldexp takes a float exponent; GLSL's an int one.
  if (name == "ldexp") return "(" + a[0] + " * exp2(" + a[1] + "))";
  // refract's index of refraction is a scalar, whatever width the analysis gave it.
  if (name == "refract") return "refract(" + a[0] + ", " + a[1] + ", " + cast(a[2], type_of(2), Type::scalar(BaseType::kFloat)) + ")";
  if (name == "saturate") return "clamp(" + a[0] + ", 0.0, 1.0)";
  if (name == "rcp") return "(" + cast("1.0", Type::scalar(BaseType::kFloat), e.resolved) + " / " + a[0] + ")";
  if (name == "log10") return "(log2(" + a[0] + ") * 0.301029995663981)";
  if (name == "fmod") return helpers.insert("fmod"), "pfx_fmod(" + a[0] + ", " + a[1] + ")";
  if (name == "mad") return "(" + a[0] + " * " + a[1] + " + " + a[2] + ")";
  if (name == "sign") return cast("sign(" + a[0] + ")", type_of(0), e.resolved);
  if (name == "isfinite") return helpers.insert("isfinite"), "pfx_isfinite(" + a[0] + ")";
  if (name == "all" || name == "any") {
    const Type& t = type_of(0);
    if (t.is_scalar()) return cast(a[0], t, Type::scalar(BaseType::kBool));
    if (t.is_matrix()) return error(e.location, name + "() of a matrix is not supported"), "false";
    return name + "(" + cast(a[0], t, t.with_base(BaseType::kBool)) + ")";
  }
  if (name == "countbits" || name == "firstbithigh" || name == "firstbitlow") {
    std::string f = name == "countbits" ? "bitCount" : name == "firstbithigh" ? "findMSB" : "findLSB";
    return cast(f + "(" + a[0] + ")", type_of(0).with_base(BaseType::kInt), e.resolved);
  }
  if (name == "asfloat" || name == "asint" || name == "asuint") {
    BaseType from = type_of(0).base;
    if (name == "asfloat") {
      if (from == BaseType::kFloat) return a[0];
      return (from == BaseType::kUint ? "uintBitsToFloat(" : "intBitsToFloat(") + a[0] + ")";
    }
    if (from == BaseType::kFloat || from == BaseType::kHalf || from == BaseType::kDouble)
      return (name == "asint" ? "floatBitsToInt(" : "floatBitsToUint(") + a[0] + ")";
    return cast(a[0], type_of(0), e.resolved);  // int <-> uint keeps the bits
  }
  if (name == "f16tof32") return helpers.insert("half"), "pfx_f16tof32(" + a[0] + ")";
  if (name == "f32tof16") return helpers.insert("half"), "pfx_f32tof16(" + a[0] + ")";
  if (name == "frexp") return helpers.insert("frexp"), "pfx_frexp(" + a[0] + ", " + a[1] + ")";
  if (name == "sincos") return "(" + a[1] + " = sin(" + a[0] + "), " + a[2] + " = cos(" + a[0] + "))";
  if (name == "mul") {
    const Type& x = type_of(0);
    const Type& y = type_of(1);
    if (x.is_scalar() || y.is_scalar()) return "(" + a[0] + " * " + a[1] + ")";
    if (x.is_vector() && y.is_vector()) return "dot(" + a[0] + ", " + a[1] + ")";
    return "(" + a[1] + " * " + a[0] + ")";  // see the matrix storage in glsl_generator.hpp
  }
  if (name == "clip") {
    if (stage_ != Stage::kPixel) return error(e.location, "clip() is only allowed in a pixel shader"), "0";
    uses_discard = true;
    helpers.insert("clip");
    return "pfx_clip(" + a[0] + ")";
  }
  if (name == "barrier") return "(memoryBarrierShared(), barrier())";
  if (name == "GroupMemoryBarrierWithGroupSync") return "(groupMemoryBarrier(), barrier())";
  if (name == "memoryBarrier" || name == "AllMemoryBarrier") return "memoryBarrier()";
  if (name == "groupMemoryBarrier" || name == "GroupMemoryBarrier") return "groupMemoryBarrier()";
  error(e.location, "the intrinsic '" + name + "' has no GLSL translation yet");
  return "0";
}

// tex1D/2D/3D*: `name` is the intrinsic, operand 0 the sampler or storage.
std::string GlslWriter::texture_call(const Expr& e, const std::string& name) {
  const Type& object = e.operands[0]->resolved;
  int d = object.dimension;
  std::string suffix = name.substr(5);  // after "texND"
  std::vector<std::string> a;
  for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
  const std::string& s = a[0];
  std::string dim = std::to_string(d);
  std::string ivec = d == 1 ? "int" : "ivec" + dim;
  std::string vec = d == 1 ? "float" : "vec" + dim;
  helpers.insert("flip");
  // Coordinates in [0, 1] with v from the top -> GL's; texel offsets likewise.
  auto uv = [&](const std::string& c) { return d == 1 ? c : "pfx_flip(" + vec + "(" + c + "))"; };
  // A texel offset, which GLSL takes only as a constant expression: folded here when the FX code
  // makes it one (from literals, static consts, swizzles...), flipped as the rows are; "" when it
  // is not constant, and HLSL's offset then moves the coordinate instead (shifted, below).
  auto offset = [&](std::size_t operand) -> std::string {
    const std::optional<ConstantValue> folded = evaluate_constant(*e.operands[operand]);
    if (!folded || folded->is_string || folded->components.empty()) return "";
    std::vector<long long> o;
    for (std::size_t i = 0; i < static_cast<std::size_t>(d); ++i)  // a scalar is splat
      o.push_back(static_cast<long long>(folded->components[std::min(i, folded->components.size() - 1)]));
    if (d == 1) return std::to_string(o[0]);
    return ivec + "(" + std::to_string(o[0]) + ", " + std::to_string(-o[1]) + (d == 3 ? ", " + std::to_string(o[2]) : std::string()) + ")";
  };
  // A GL coordinate moved by a texel offset that is not constant, in texels of `level`.
  auto shifted = [&](const std::string& coordinate, std::size_t operand, const std::string& level) {
    const std::string size = "textureSize(" + s + ", " + level + ")";
    if (d == 1) return "(" + coordinate + " + float(" + a[operand] + ") / float(" + size + "))";
    const std::string v = vec + "(" + a[operand] + ")";
    return "(" + coordinate + " + " + vec + "(" + v + ".x, -(" + v + ".y)" + (d == 3 ? ", " + v + ".z" : std::string()) +
           ") / " + vec + "(" + size + "))";
  };
  auto texel = [&](const std::string& c, const std::string& height) {
    return d == 1 ? "int(" + c + ")" : "pfx_flip_texel(" + ivec + "(" + c + "), " + height + ")";
  };
  auto component = [&](const std::string& text, int count) {
    std::string letters = std::string("xyzw").substr(0, static_cast<std::size_t>(count));
    return "(" + text + ")." + letters;
  };
  const Type& c1 = e.operands.size() > 1 ? e.operands[1]->resolved : object;

  if (object.base == BaseType::kStorage) {
    if (suffix == "size") return "imageSize(" + s + ")";
    if (suffix == "store") {
      std::string value = a[2];
      const Type& vt = e.operands[2]->resolved;
      Type four = Type::vector(object.element_base == BaseType::kInt || object.element_base == BaseType::kUint ? object.element_base : BaseType::kFloat, 4);
      if (vt.components() < 4) {
        std::string padded = type(four) + "(" + cast(value, vt, vt.with_base(four.base));
        for (int i = vt.components(); i < 4; ++i) padded += i == 3 ? ", 1" : ", 0";
        value = padded + ")";
      } else {
        value = cast(value, vt, four);
      }
      return "imageStore(" + s + ", " + texel(a[1], "imageSize(" + s + ").y") + ", " + value + ")";
    }
    if (suffix == "fetch") return sampled("imageLoad(" + s + ", " + texel(a[1], "imageSize(" + s + ").y") + ")", e);
    return error(e.location, name + "() does not take a storage"), "0";
  }
  if (suffix == "size") return "textureSize(" + s + ", " + (a.size() > 1 ? "int(" + a[1] + ")" : "0") + ")";
  if (suffix == "" || suffix == "offset") {
    if (a.size() < 3) return sampled("texture(" + s + ", " + uv(a[1]) + ")", e);
    const std::string o = offset(2);
    if (o.empty()) return sampled("texture(" + s + ", " + shifted(uv(a[1]), 2, "0") + ")", e);
    return sampled("textureOffset(" + s + ", " + uv(a[1]) + ", " + o + ")", e);
  }
  if (suffix == "lod" || suffix == "lodoffset" || suffix == "bias" || suffix == "proj") {
    // The coordinate is a float4: xy(z) the position, w the level, bias or divisor.
    std::string c = "(" + a[1] + ")";
    std::string position = c + (d == 1 ? ".x" : d == 2 ? ".xy" : ".xyz");
    if (suffix == "proj") return sampled("texture(" + s + ", " + uv(position + " / " + c + ".w") + ")", e);
    if (suffix == "bias") return sampled("texture(" + s + ", " + uv(position) + ", " + c + ".w)", e);
    if (a.size() > 2) {
      const std::string o = offset(2);
      if (o.empty())
        return sampled("textureLod(" + s + ", " + shifted(uv(position), 2, "int(" + c + ".w)") + ", " + c + ".w)", e);
      return sampled("textureLodOffset(" + s + ", " + uv(position) + ", " + c + ".w, " + o + ")", e);
    }
    return sampled("textureLod(" + s + ", " + uv(position) + ", " + c + ".w)", e);
  }
  if (suffix == "fetch") {
    // tex2Dfetch(s, int2 position [, int level]) or ReShade 4's tex2Dfetch(s, int4(x, y, 0, level)).
    std::string position = a[1], level = a.size() > 2 ? "int(" + a[2] + ")" : "0";
    if (c1.components() == 4 && d < 4) {
      position = "(" + a[1] + ")" + (d == 1 ? ".x" : d == 2 ? ".xy" : ".xyz");
      level = "int((" + a[1] + ").w)";
    }
    return sampled("texelFetch(" + s + ", " + texel(position, "textureSize(" + s + ", " + level + ").y") + ", " + level + ")", e);
  }
  if (suffix == "grad") {
    auto gradient = [&](const std::string& g) { return d == 1 ? g : "pfx_flip_offset(" + vec + "(" + g + "))"; };
    const std::string o = a.size() > 4 ? offset(4) : "";
    const std::string at = a.size() > 4 && o.empty() ? shifted(uv(a[1]), 4, "0") : uv(a[1]);
    std::string text = (o.empty() ? "textureGrad(" : "textureGradOffset(") + s + ", " + at + ", " + gradient(a[2]) + ", " + gradient(a[3]);
    if (!o.empty()) text += ", " + o;
    return sampled(text + ")", e);
  }
  if (suffix.compare(0, 6, "gather") == 0) {
    if (d != 2) return error(e.location, name + "() needs a 2D sampler"), "0";
    char channel = suffix.size() > 6 ? suffix[6] : 'R';
    int comp = channel == 'G' ? 1 : channel == 'B' ? 2 : channel == 'A' ? 3 : 0;
    const std::string o = a.size() > 2 ? offset(2) : "";
    const std::string at = a.size() > 2 && o.empty() ? shifted(uv(a[1]), 2, "0") : uv(a[1]);
    std::string text = !o.empty() ? "textureGatherOffset(" + s + ", " + at + ", " + o + ", " + std::to_string(comp) + ")"
                                  : "textureGather(" + s + ", " + at + ", " + std::to_string(comp) + ")";
    // GL gathers (i0,j1) (i1,j1) (i1,j0) (i0,j0) with j1 the upper row in GL, the lower in FX.
    return component(text, 4) + ".wzyx";
  }
  error(e.location, "the intrinsic '" + name + "' has no GLSL translation yet");
  return "0";
}

// A sampling result (a GLSL gvec4) as the FX call's type: the sampler's element type.
std::string GlslWriter::sampled(const std::string& call, const Expr& e) {
  const Type& t = e.resolved;
  if (t.is_scalar()) return "(" + call + ").x";
  if (t.is_vector() && t.rows < 4) return "(" + call + ")." + std::string("xyzw").substr(0, static_cast<std::size_t>(t.rows));
  return call;
}

}  // namespace pfx::fx
