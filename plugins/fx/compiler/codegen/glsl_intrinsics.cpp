// HLSL's and ReShade's intrinsics in GLSL. Each keeps its HLSL meaning: fmod truncates, frac is
// x - floor(x), sign returns int, round rounds half to even, mul's operands swap (the matrix
// storage of glsl_generator.hpp), and every texture access flips v between FX's top-left origin
// and GL's bottom-left one.
#include <algorithm>
#include <map>

#include "glsl_writer.hpp"

#include "../sema/constant_value.hpp"
#include "../text_lists.hpp"

namespace pfx::fx {
namespace {

using I = Intrinsic;

// The GLSL function of the same arguments and meaning, or null.
const char* same_in_glsl(Intrinsic id) {
  switch (id) {
    case I::kAbs: return "abs";                 case I::kAcos: return "acos";
    case I::kAsin: return "asin";               case I::kAtan: return "atan";
    case I::kCeil: return "ceil";               case I::kClamp: return "clamp";
    case I::kCos: return "cos";                 case I::kCosh: return "cosh";
    case I::kCross: return "cross";             case I::kDegrees: return "degrees";
    case I::kDeterminant: return "determinant"; case I::kDistance: return "distance";
    case I::kDot: return "dot";                 case I::kExp: return "exp";
    case I::kExp2: return "exp2";               case I::kFloor: return "floor";
    case I::kFwidth: return "fwidth";           case I::kIsinf: return "isinf";
    case I::kIsnan: return "isnan";             case I::kLength: return "length";
    case I::kLog: return "log";                 case I::kLog2: return "log2";
    case I::kMax: return "max";                 case I::kMin: return "min";
    case I::kNormalize: return "normalize";     case I::kPow: return "pow";
    case I::kRadians: return "radians";         case I::kReflect: return "reflect";
    case I::kSin: return "sin";                 case I::kSinh: return "sinh";
    case I::kSmoothstep: return "smoothstep";   case I::kSqrt: return "sqrt";
    case I::kStep: return "step";               case I::kTan: return "tan";
    case I::kTanh: return "tanh";               case I::kTranspose: return "transpose";
    case I::kTrunc: return "trunc";             case I::kFrac: return "fract";
    case I::kLerp: return "mix";                case I::kRsqrt: return "inversesqrt";
    case I::kAtan2: return "atan";              case I::kRound: return "roundEven";
    case I::kDdx: return "dFdx";                case I::kDdxCoarse: return "dFdxCoarse";
    case I::kDdxFine: return "dFdxFine";        case I::kReversebits: return "bitfieldReverse";
    case I::kFaceforward: return "faceforward"; case I::kModf: return "modf";
    default: return nullptr;
  }
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
  std::string storage() {
    const std::string& s = a_[0];
    if (e_.intrinsic == I::kTexSize) return "imageSize(" + s + ")";
    if (e_.intrinsic == I::kTexStore) {
      const std::string value = stored_value();
      return "imageStore(" + s + ", " + texel(a_[1], "imageSize(" + s + ").y") + ", " + value + ")";
    }
    if (e_.intrinsic == I::kTexFetch) return sampled("imageLoad(" + s + ", " + texel(a_[1], "imageSize(" + s + ").y") + ")", e_);
    return writer_.error(e_.location, e_.text + "() does not take a storage"), "0";
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
  std::string sample_by_w() const {
    const std::string& s = a_[0];
    std::string c = "(" + a_[1] + ")";
    std::string position = c + (d_ == 1 ? ".x" : d_ == 2 ? ".xy" : ".xyz");
    if (e_.intrinsic == I::kTexSampleProj) return sampled("texture(" + s + ", " + uv(position + " / " + c + ".w") + ")", e_);
    if (e_.intrinsic == I::kTexSampleBias) return sampled("texture(" + s + ", " + uv(position) + ", " + c + ".w)", e_);
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
  std::string gather() {
    const std::string& s = a_[0];
    if (d_ != 2) return writer_.error(e_.location, e_.text + "() needs a 2D sampler"), "0";
    const Intrinsic id = e_.intrinsic;
    int comp = id == I::kTexGatherG ? 1 : id == I::kTexGatherB ? 2 : id == I::kTexGatherA ? 3 : 0;
    const std::string o = a_.size() > 2 ? offset(2) : "";
    const std::string at = a_.size() > 2 && o.empty() ? shifted(uv(a_[1]), 2, "0") : uv(a_[1]);
    std::string text = !o.empty()
                           ? "textureGatherOffset(" + s + ", " + at + ", " + o + ", " + std::to_string(comp) + ")"
                           : "textureGather(" + s + ", " + at + ", " + std::to_string(comp) + ")";
    // GL gathers (i0,j1) (i1,j1) (i1,j0) (i0,j0) with j1 the upper row in GL, the lower in FX
    // (and in Vulkan, whose rows run as FX's).
    return writer_.vulkan() ? text : "(" + text + ").xyzw.wzyx";
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
    return ivec_ + "(" + std::to_string(o[0]) + ", " + std::to_string(writer_.vulkan() ? o[1] : -o[1]) +
           (d_ == 3 ? ", " + std::to_string(o[2]) : std::string()) + ")";
  }

  // A GL coordinate moved by a texel offset that is not constant, in texels of `level`.
  std::string shifted(const std::string& coordinate, std::size_t operand, const std::string& level) const {
    const std::string size = "textureSize(" + a_[0] + ", " + level + ")";
    if (d_ == 1) return "(" + coordinate + " + float(" + a_[operand] + ") / float(" + size + "))";
    const std::string v = vec_ + "(" + a_[operand] + ")";
    return "(" + coordinate + " + " + vec_ + "(" + v + ".x, " + (writer_.vulkan() ? "" : "-") + "(" + v + ".y)" +
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
  const Intrinsic id = e.intrinsic;
  for (const ExprPtr& operand : e.operands)
    if (held_as_rows(operand->resolved) && id != I::kAll && id != I::kAny)
      return error(e.location, e.text + "() of an integer or bool matrix is not supported"), "0";
  if (const char* same = same_in_glsl(id)) {
    std::vector<std::string> a;
    for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
    return std::string(same) + "(" + joined(a) + ")";
  }
  switch (id) {
    case I::kTexSample: case I::kTexSampleOffset: case I::kTexSampleLod: case I::kTexSampleLodOffset:
    case I::kTexSampleBias: case I::kTexSampleProj: case I::kTexSampleGrad: case I::kTexFetch: case I::kTexSize:
    case I::kTexStore: case I::kTexGather: case I::kTexGatherR: case I::kTexGatherG: case I::kTexGatherB:
    case I::kTexGatherA:
      return texture_call(e);
    case I::kAtomicAdd: case I::kAtomicAnd: case I::kAtomicOr: case I::kAtomicXor: case I::kAtomicMin:
    case I::kAtomicMax: case I::kAtomicExchange: case I::kAtomicCompareExchange:
      return atomic(e);
    case I::kAbs: case I::kAcos: case I::kAsin: case I::kAtan: case I::kCeil: case I::kClamp: case I::kCos:
    case I::kCosh: case I::kCross: case I::kDegrees: case I::kDeterminant: case I::kDistance: case I::kDot:
    case I::kExp: case I::kExp2: case I::kFloor: case I::kFwidth: case I::kIsinf: case I::kIsnan: case I::kLength:
    case I::kLog: case I::kLog2: case I::kMax: case I::kMin: case I::kNormalize: case I::kPow: case I::kRadians:
    case I::kReflect: case I::kSin: case I::kSinh: case I::kSmoothstep: case I::kSqrt: case I::kStep: case I::kTan:
    case I::kTanh: case I::kTranspose: case I::kTrunc: case I::kFrac: case I::kLerp: case I::kRsqrt: case I::kAtan2:
    case I::kRound: case I::kDdx: case I::kDdxCoarse: case I::kDdxFine: case I::kReversebits: case I::kFaceforward:
    case I::kModf:
      break;  // same_in_glsl, above
    case I::kDdy: case I::kDdyCoarse: case I::kDdyFine: case I::kLdexp: case I::kRefract: case I::kSaturate: case I::kRcp:
    case I::kLog10: case I::kFmod: case I::kMad: case I::kSign: case I::kIsfinite: case I::kAll: case I::kAny:
    case I::kCountbits: case I::kFirstbithigh: case I::kFirstbitlow: case I::kAsfloat: case I::kAsint: case I::kAsuint:
    case I::kF16tof32: case I::kF32tof16: case I::kFrexp: case I::kSincos: case I::kMul: case I::kClip: case I::kBarrier:
    case I::kGroupMemoryBarrierWithGroupSync: case I::kMemoryBarrier: case I::kGroupMemoryBarrier:
      return with_hlsl_meaning(e);
    case I::kNone: case I::kCount:
      break;
  }  // no default: an intrinsic added to the table without a case here does not compile (-Wswitch)
  error(e.location, "the intrinsic '" + e.text + "' has no GLSL translation yet");
  return "0";
}

// Intrinsics whose HLSL meaning GLSL spells otherwise.
std::string GlslWriter::with_hlsl_meaning(const Expr& e) {
  std::vector<std::string> a;
  for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
  auto type_of = [&](std::size_t i) -> const Type& { return e.operands[i]->resolved; };
  switch (e.intrinsic) {
    // FX's y grows downwards, GL's upwards (Vulkan's downwards).
    case I::kDdy: return "(" + std::string(vulkan() ? "" : "-") + "dFdy(" + a[0] + "))";
    case I::kDdyCoarse: return "(" + std::string(vulkan() ? "" : "-") + "dFdyCoarse(" + a[0] + "))";
    case I::kDdyFine: return "(" + std::string(vulkan() ? "" : "-") + "dFdyFine(" + a[0] + "))";
    // HLSL's ldexp takes a float exponent; GLSL's an int one.
    case I::kLdexp: return "(" + a[0] + " * exp2(" + a[1] + "))";
    // refract's index of refraction is a scalar, whatever width the analysis gave it.
    case I::kRefract: return "refract(" + a[0] + ", " + a[1] + ", " + cast(a[2], type_of(2), Type::scalar(BaseType::kFloat)) + ")";
    case I::kSaturate: return "clamp(" + a[0] + ", 0.0, 1.0)";
    case I::kRcp: return "(" + cast("1.0", Type::scalar(BaseType::kFloat), e.resolved) + " / " + a[0] + ")";
    case I::kLog10: return "(log2(" + a[0] + ") * 0.301029995663981)";
    case I::kFmod: return helpers.insert("fmod"), "pfx_fmod(" + a[0] + ", " + a[1] + ")";
    case I::kMad: return "(" + a[0] + " * " + a[1] + " + " + a[2] + ")";
    // sign() is -1, 0 or 1: a plain conversion, not the saturating one.
    case I::kSign: return type(e.resolved) + "(sign(" + a[0] + "))";
    case I::kIsfinite: return helpers.insert("isfinite"), "pfx_isfinite(" + a[0] + ")";
    case I::kAll: return all_or_any("all", type_of(0), a[0]);
    case I::kAny: return all_or_any("any", type_of(0), a[0]);
    case I::kCountbits: return cast("bitCount(" + a[0] + ")", type_of(0).with_base(BaseType::kInt), e.resolved);
    case I::kFirstbithigh: return cast("findMSB(" + a[0] + ")", type_of(0).with_base(BaseType::kInt), e.resolved);
    case I::kFirstbitlow: return cast("findLSB(" + a[0] + ")", type_of(0).with_base(BaseType::kInt), e.resolved);
    case I::kAsfloat: case I::kAsint: case I::kAsuint: return reinterpreted(e, a[0]);
    case I::kF16tof32: return helpers.insert("half"), "pfx_f16tof32(" + a[0] + ")";
    case I::kF32tof16: return helpers.insert("half"), "pfx_f32tof16(" + a[0] + ")";
    case I::kFrexp: return helpers.insert("frexp"), "pfx_frexp(" + a[0] + ", " + a[1] + ")";
    case I::kSincos: return "(" + a[1] + " = sin(" + a[0] + "), " + a[2] + " = cos(" + a[0] + "))";
    case I::kMul: {
      const Type& x = type_of(0);
      const Type& y = type_of(1);
      if (x.is_scalar() || y.is_scalar()) return "(" + a[0] + " * " + a[1] + ")";
      if (x.is_vector() && y.is_vector()) return "dot(" + a[0] + ", " + a[1] + ")";
      return "(" + a[1] + " * " + a[0] + ")";  // see the matrix storage in glsl_generator.hpp
    }
    case I::kClip:
      if (stage_ != Stage::kPixel) return error(e.location, "clip() is only allowed in a pixel shader"), "0";
      uses_discard = true;
      helpers.insert("clip");
      return "pfx_clip(" + a[0] + ")";
    case I::kBarrier: return "(memoryBarrierShared(), barrier())";
    case I::kGroupMemoryBarrierWithGroupSync: return "(groupMemoryBarrier(), barrier())";
    case I::kMemoryBarrier: return "memoryBarrier()";
    case I::kGroupMemoryBarrier: return "groupMemoryBarrier()";
    default: break;
  }
  error(e.location, "the intrinsic '" + e.text + "' has no GLSL translation yet");
  return "0";
}

// asfloat, asint and asuint: the same bits as another type.
std::string GlslWriter::reinterpreted(const Expr& e, const std::string& value) {
  const Type& from = e.operands[0]->resolved;
  if (e.intrinsic == I::kAsfloat) {
    if (from.base == BaseType::kFloat) return value;
    return (from.base == BaseType::kUint ? "uintBitsToFloat(" : "intBitsToFloat(") + value + ")";
  }
  if (from.base == BaseType::kFloat || from.base == BaseType::kHalf || from.base == BaseType::kDouble)
    return (e.intrinsic == I::kAsint ? "floatBitsToInt(" : "floatBitsToUint(") + value + ")";
  return cast(value, from, e.resolved);  // int <-> uint keeps the bits
}

// atomic*: on a storage's texel (its row counted from the top) or on a variable.
std::string GlslWriter::atomic(const Expr& e) {
  std::vector<std::string> a;
  for (const ExprPtr& operand : e.operands) a.push_back(expr(*operand));
  std::string op;
  switch (e.intrinsic) {
    case I::kAtomicAdd: op = "Add"; break;
    case I::kAtomicAnd: op = "And"; break;
    case I::kAtomicOr: op = "Or"; break;
    case I::kAtomicXor: op = "Xor"; break;
    case I::kAtomicMin: op = "Min"; break;
    case I::kAtomicMax: op = "Max"; break;
    case I::kAtomicExchange: op = "Exchange"; break;
    default: op = "CompSwap"; break;
  }
  const Type& object = e.operands[0]->resolved;
  if (object.base != BaseType::kStorage) return "atomic" + op + "(" + joined(a) + ")";
  helpers.insert("flip");
  std::string coordinate = object.dimension == 1 ? "int(" + a[1] + ")"
                                                 : "pfx_flip_texel(ivec" + std::to_string(object.dimension) + "(" + a[1] +
                                                       "), imageSize(" + a[0] + ").y)";
  std::vector<std::string> rest(a.begin() + 2, a.end());
  return "imageAtomic" + op + "(" + a[0] + ", " + coordinate + ", " + joined(rest) + ")";
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

// tex1D/2D/3D*: operand 0 the sampler or storage.
std::string GlslWriter::texture_call(const Expr& e) {
  TextureCall call(*this, e);
  if (call.on_storage()) return call.storage();
  switch (e.intrinsic) {
    case I::kTexSize: return call.size();
    case I::kTexSample: case I::kTexSampleOffset: return call.sample();
    case I::kTexSampleLod: case I::kTexSampleLodOffset: case I::kTexSampleBias: case I::kTexSampleProj: return call.sample_by_w();
    case I::kTexFetch: return call.fetch();
    case I::kTexSampleGrad: return call.grad();
    case I::kTexGather: case I::kTexGatherR: case I::kTexGatherG: case I::kTexGatherB: case I::kTexGatherA: return call.gather();
    default: break;
  }
  error(e.location, "the intrinsic '" + e.text + "' has no GLSL translation yet");
  return "0";
}

}  // namespace pfx::fx
