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

// A sampling result (a GLSL gvec4) as the FX call's type: the sampler's element type.
std::string sampled(const std::string& call, const Expr& e) {
  const Type& t = e.resolved;
  if (t.is_scalar()) return "(" + call + ").x";
  if (t.is_vector() && t.rows < 4)
    return "(" + call + ")." + std::string("xyzw").substr(0, static_cast<std::size_t>(t.rows));
  return call;
}

// One tex1D/2D/3D* call, one method a form: the operands written once, and the conversions
// between FX's coordinates (v from the top) and GL's (v from the bottom) that the forms share.
class TextureCall {
 public:
  TextureCall(GlslWriter& writer, const Expr& e)
      : writer_(writer), e_(e), object_(e.operands[0]->resolved), d_(object_.dimension) {
    for (const ExprPtr& operand : e.operands) a_.push_back(writer.expr(*operand));
    const std::string dim = std::to_string(d_);
    ivec_ = d_ == 1 ? "int" : "ivec" + dim;
    vec_ = d_ == 1 ? "float" : "vec" + dim;
    writer.helpers.insert("flip");
  }

  bool on_storage() const { return object_.base == BaseType::kStorage; }

  // A storage takes only size, store and fetch.
  std::string storage(const std::string& suffix, const std::string& name) {
    const std::string& s = a_[0];
    if (suffix == "size") return "imageSize(" + s + ")";
    if (suffix == "store") {
      const std::string value = stored_value();
      return "imageStore(" + s + ", " + texel(a_[1], "imageSize(" + s + ").y") + ", " + value + ")";
    }
    if (suffix == "fetch") return sampled("imageLoad(" + s + ", " + texel(a_[1], "imageSize(" + s + ").y") + ")", e_);
    return writer_.error(e_.location, name + "() does not take a storage"), "0";
  }

  std::string size() const {
    return "textureSize(" + a_[0] + ", " + (a_.size() > 1 ? "int(" + a_[1] + ")" : "0") + ")";
  }

  // tex2D and tex2Doffset.
  std::string sample() const {
    const std::string& s = a_[0];
    if (a_.size() < 3) return sampled("texture(" + s + ", " + uv(a_[1]) + ")", e_);
    const std::string o = offset(2);
    if (o.empty()) return sampled("texture(" + s + ", " + shifted(uv(a_[1]), 2, "0") + ")", e_);
    return sampled("textureOffset(" + s + ", " + uv(a_[1]) + ", " + o + ")", e_);
  }

  // lod, lodoffset, bias and proj: the coordinate is a float4, xy(z) the position, w the level,
  // bias or divisor.
  std::string sample_by_w(const std::string& suffix) const {
    const std::string& s = a_[0];
    std::string c = "(" + a_[1] + ")";
    std::string position = c + (d_ == 1 ? ".x" : d_ == 2 ? ".xy" : ".xyz");
    if (suffix == "proj") return sampled("texture(" + s + ", " + uv(position + " / " + c + ".w") + ")", e_);
    if (suffix == "bias") return sampled("texture(" + s + ", " + uv(position) + ", " + c + ".w)", e_);
    if (a_.size() > 2) {
      const std::string o = offset(2);
      if (o.empty())
        return sampled("textureLod(" + s + ", " + shifted(uv(position), 2, "int(" + c + ".w)") + ", " + c + ".w)", e_);
      return sampled("textureLodOffset(" + s + ", " + uv(position) + ", " + c + ".w, " + o + ")", e_);
    }
    return sampled("textureLod(" + s + ", " + uv(position) + ", " + c + ".w)", e_);
  }

  // tex2Dfetch(s, int2 position [, int level]) or ReShade 4's tex2Dfetch(s, int4(x, y, 0, level)).
  std::string fetch() const {
    const std::string& s = a_[0];
    const Type& c1 = e_.operands.size() > 1 ? e_.operands[1]->resolved : object_;
    std::string position = a_[1], level = a_.size() > 2 ? "int(" + a_[2] + ")" : "0";
    if (c1.components() == 4 && d_ < 4) {
      position = "(" + a_[1] + ")" + (d_ == 1 ? ".x" : d_ == 2 ? ".xy" : ".xyz");
      level = "int((" + a_[1] + ").w)";
    }
    return sampled(
        "texelFetch(" + s + ", " + texel(position, "textureSize(" + s + ", " + level + ").y") + ", " + level + ")", e_);
  }

  std::string grad() const {
    const std::string& s = a_[0];
    auto gradient = [&](const std::string& g) { return d_ == 1 ? g : "pfx_flip_offset(" + vec_ + "(" + g + "))"; };
    const std::string o = a_.size() > 4 ? offset(4) : "";
    const std::string at = a_.size() > 4 && o.empty() ? shifted(uv(a_[1]), 4, "0") : uv(a_[1]);
    std::string text = (o.empty() ? "textureGrad(" : "textureGradOffset(") + s + ", " + at + ", " + gradient(a_[2]) +
                       ", " + gradient(a_[3]);
    if (!o.empty()) text += ", " + o;
    return sampled(text + ")", e_);
  }

  // gather, gatherR, gatherG, gatherB, gatherA: 2D only.
  std::string gather(const std::string& suffix, const std::string& name) {
    const std::string& s = a_[0];
    if (d_ != 2) return writer_.error(e_.location, name + "() needs a 2D sampler"), "0";
    char channel = suffix.size() > 6 ? suffix[6] : 'R';
    int comp = channel == 'G' ? 1 : channel == 'B' ? 2 : channel == 'A' ? 3 : 0;
    const std::string o = a_.size() > 2 ? offset(2) : "";
    const std::string at = a_.size() > 2 && o.empty() ? shifted(uv(a_[1]), 2, "0") : uv(a_[1]);
    std::string text = !o.empty()
                           ? "textureGatherOffset(" + s + ", " + at + ", " + o + ", " + std::to_string(comp) + ")"
                           : "textureGather(" + s + ", " + at + ", " + std::to_string(comp) + ")";
    // GL gathers (i0,j1) (i1,j1) (i1,j0) (i0,j0) with j1 the upper row in GL, the lower in FX.
    return "(" + text + ").xyzw.wzyx";
  }

 private:
  // Coordinates in [0, 1] with v from the top -> GL's; texel offsets likewise.
  std::string uv(const std::string& c) const { return d_ == 1 ? c : "pfx_flip(" + vec_ + "(" + c + "))"; }

  // A texel offset, which GLSL takes only as a constant expression: folded here when the FX code
  // makes it one (from literals, static consts, swizzles...), flipped as the rows are; "" when it
  // is not constant, and HLSL's offset then moves the coordinate instead (shifted, below).
  std::string offset(std::size_t operand) const {
    const std::optional<ConstantValue> folded = evaluate_constant(*e_.operands[operand]);
    if (!folded || folded->is_string || folded->components.empty()) return "";
    std::vector<long long> o;
    for (std::size_t i = 0; i < static_cast<std::size_t>(d_); ++i)  // a scalar is splat
      o.push_back(static_cast<long long>(folded->components[std::min(i, folded->components.size() - 1)]));
    if (d_ == 1) return std::to_string(o[0]);
    return ivec_ + "(" + std::to_string(o[0]) + ", " + std::to_string(-o[1]) +
           (d_ == 3 ? ", " + std::to_string(o[2]) : std::string()) + ")";
  }

  // A GL coordinate moved by a texel offset that is not constant, in texels of `level`.
  std::string shifted(const std::string& coordinate, std::size_t operand, const std::string& level) const {
    const std::string size = "textureSize(" + a_[0] + ", " + level + ")";
    if (d_ == 1) return "(" + coordinate + " + float(" + a_[operand] + ") / float(" + size + "))";
    const std::string v = vec_ + "(" + a_[operand] + ")";
    return "(" + coordinate + " + " + vec_ + "(" + v + ".x, -(" + v + ".y)" +
           (d_ == 3 ? ", " + v + ".z" : std::string()) + ") / " + vec_ + "(" + size + "))";
  }

  // An integer position with its row counted from the top -> GL's, in an image `height` high.
  std::string texel(const std::string& c, const std::string& height) const {
    return d_ == 1 ? "int(" + c + ")" : "pfx_flip_texel(" + ivec_ + "(" + c + "), " + height + ")";
  }

  // tex2Dstore's value as the gvec4 imageStore takes: the storage's element type, missing
  // channels 0 and alpha 1.
  std::string stored_value() {
    const Type& vt = e_.operands[2]->resolved;
    const BaseType element = object_.element_base;
    Type four = Type::vector(element == BaseType::kInt || element == BaseType::kUint ? element : BaseType::kFloat, 4);
    if (vt.components() >= 4) return writer_.cast(a_[2], vt, four);
    std::string padded = writer_.type(four) + "(" + writer_.cast(a_[2], vt, vt.with_base(four.base));
    for (int i = vt.components(); i < 4; ++i) padded += i == 3 ? ", 1" : ", 0";
    return padded + ")";
  }

  GlslWriter& writer_;
  const Expr& e_;
  const Type& object_;
  int d_;
  std::vector<std::string> a_;  // the operands in GLSL; a_[0] the sampler or storage
  std::string ivec_, vec_;      // the integer and float vectors of the object's dimension
};

}  // namespace

std::string GlslWriter::intrinsic(const Expr& e) {
  const std::string& name = e.intrinsic;
  std::vector<std::string> a;
  for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
  auto type_of = [&](std::size_t i) -> const Type& { return e.operands[i]->resolved; };
  for (const ExprPtr& operand : e.operands)
    if (held_as_rows(operand->resolved) && name != "all" && name != "any")
      return error(e.location, name + "() of an integer or bool matrix is not supported"), "0";
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
  if (name == "all" || name == "any") return all_or_any(name, type_of(0), a[0]);
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

// all() and any() of a scalar, vector or matrix: true when every, or some, component is not zero.
std::string GlslWriter::all_or_any(const std::string& name, const Type& t, const std::string& value) {
  if (t.is_scalar()) return cast(value, t, Type::scalar(BaseType::kBool));
  if (t.is_vector()) return name + "(" + cast(value, t, t.with_base(BaseType::kBool)) + ")";
  std::string m = temporary(t), zero = type(row_of(t)) + "(0)";  // a matrix row by row
  std::string text = "(" + m + " = " + value + ", ";
  for (int r = 0; r < t.rows; ++r)
    text += (r ? (name == "all" ? " && " : " || ") : "") + name + "(notEqual(" + m + "[" + std::to_string(r) + "], " + zero + "))";
  return text + ")";
}

// tex1D/2D/3D*: `name` is the intrinsic, operand 0 the sampler or storage.
std::string GlslWriter::texture_call(const Expr& e, const std::string& name) {
  TextureCall call(*this, e);
  const std::string suffix = name.substr(5);  // after "texND"
  if (call.on_storage()) return call.storage(suffix, name);
  if (suffix == "size") return call.size();
  if (suffix == "" || suffix == "offset") return call.sample();
  if (suffix == "lod" || suffix == "lodoffset" || suffix == "bias" || suffix == "proj") return call.sample_by_w(suffix);
  if (suffix == "fetch") return call.fetch();
  if (suffix == "grad") return call.grad();
  if (suffix.compare(0, 6, "gather") == 0) return call.gather(suffix, name);
  error(e.location, "the intrinsic '" + name + "' has no GLSL translation yet");
  return "0";
}

}  // namespace pfx::fx
