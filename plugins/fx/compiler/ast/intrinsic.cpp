#include "intrinsic.hpp"

#include <map>
#include <vector>

namespace pfx::fx {
namespace {

using I = Intrinsic;
using R = IntrinsicRule;

std::vector<IntrinsicInfo> rows() {
  std::vector<IntrinsicInfo> t = {
      {I::kAcos, "acos", R::kFloatWise, 1, 1},         {I::kAsin, "asin", R::kFloatWise, 1, 1},
      {I::kAtan, "atan", R::kFloatWise, 1, 1},         {I::kCos, "cos", R::kFloatWise, 1, 1},
      {I::kCosh, "cosh", R::kFloatWise, 1, 1},         {I::kSin, "sin", R::kFloatWise, 1, 1},
      {I::kSinh, "sinh", R::kFloatWise, 1, 1},         {I::kTan, "tan", R::kFloatWise, 1, 1},
      {I::kTanh, "tanh", R::kFloatWise, 1, 1},         {I::kExp, "exp", R::kFloatWise, 1, 1},
      {I::kExp2, "exp2", R::kFloatWise, 1, 1},         {I::kLog, "log", R::kFloatWise, 1, 1},
      {I::kLog2, "log2", R::kFloatWise, 1, 1},         {I::kLog10, "log10", R::kFloatWise, 1, 1},
      {I::kSqrt, "sqrt", R::kFloatWise, 1, 1},         {I::kRsqrt, "rsqrt", R::kFloatWise, 1, 1},
      {I::kRcp, "rcp", R::kFloatWise, 1, 1},           {I::kCeil, "ceil", R::kFloatWise, 1, 1},
      {I::kFloor, "floor", R::kFloatWise, 1, 1},       {I::kFrac, "frac", R::kFloatWise, 1, 1},
      {I::kRound, "round", R::kFloatWise, 1, 1},       {I::kTrunc, "trunc", R::kFloatWise, 1, 1},
      {I::kSaturate, "saturate", R::kFloatWise, 1, 1}, {I::kDegrees, "degrees", R::kFloatWise, 1, 1},
      {I::kRadians, "radians", R::kFloatWise, 1, 1},   {I::kDdx, "ddx", R::kFloatWise, 1, 1},
      {I::kDdy, "ddy", R::kFloatWise, 1, 1},           {I::kDdxCoarse, "ddx_coarse", R::kFloatWise, 1, 1},
      {I::kDdyCoarse, "ddy_coarse", R::kFloatWise, 1, 1}, {I::kDdxFine, "ddx_fine", R::kFloatWise, 1, 1},
      {I::kDdyFine, "ddy_fine", R::kFloatWise, 1, 1},  {I::kFwidth, "fwidth", R::kFloatWise, 1, 1},
      {I::kNormalize, "normalize", R::kFloatWise, 1, 1}, {I::kPow, "pow", R::kFloatWise, 2, 2},
      {I::kAtan2, "atan2", R::kFloatWise, 2, 2},       {I::kFmod, "fmod", R::kFloatWise, 2, 2},
      {I::kStep, "step", R::kFloatWise, 2, 2},         {I::kLdexp, "ldexp", R::kFloatWise, 2, 2},
      {I::kReflect, "reflect", R::kFloatWise, 2, 2},   {I::kLerp, "lerp", R::kFloatWise, 3, 3},
      {I::kSmoothstep, "smoothstep", R::kFloatWise, 3, 3}, {I::kRefract, "refract", R::kFloatWise, 3, 3},
      {I::kFaceforward, "faceforward", R::kFloatWise, 3, 3},
      {I::kAbs, "abs", R::kNumberWise, 1, 1},          {I::kMin, "min", R::kNumberWise, 2, 2},
      {I::kMax, "max", R::kNumberWise, 2, 2},          {I::kClamp, "clamp", R::kNumberWise, 3, 3},
      {I::kMad, "mad", R::kNumberWise, 3, 3},
      {I::kIsnan, "isnan", R::kBoolWise, 1, 1},        {I::kIsinf, "isinf", R::kBoolWise, 1, 1},
      {I::kIsfinite, "isfinite", R::kBoolWise, 1, 1},  {I::kSign, "sign", R::kIntWise, 1, 1},
      {I::kCountbits, "countbits", R::kUintWise, 1, 1}, {I::kReversebits, "reversebits", R::kUintWise, 1, 1},
      {I::kFirstbithigh, "firstbithigh", R::kUintWise, 1, 1}, {I::kFirstbitlow, "firstbitlow", R::kUintWise, 1, 1},
      {I::kAsfloat, "asfloat", R::kAsFloat, 1, 1},     {I::kAsint, "asint", R::kAsInt, 1, 1},
      {I::kAsuint, "asuint", R::kAsUint, 1, 1},        {I::kF16tof32, "f16tof32", R::kHalfToFloat, 1, 1},
      {I::kF32tof16, "f32tof16", R::kFloatToHalf, 1, 1},
      {I::kDot, "dot", R::kScalarFloat, 2, 2},         {I::kDistance, "distance", R::kScalarFloat, 2, 2},
      {I::kLength, "length", R::kScalarFloat, 1, 1},   {I::kDeterminant, "determinant", R::kScalarFloat, 1, 1},
      {I::kCross, "cross", R::kCross, 2, 2},           {I::kTranspose, "transpose", R::kTranspose, 1, 1},
      {I::kMul, "mul", R::kMul, 2, 2},                 {I::kAll, "all", R::kAllAny, 1, 1},
      {I::kAny, "any", R::kAllAny, 1, 1},
      {I::kSincos, "sincos", R::kSinCos, 3, 3},        {I::kModf, "modf", R::kOutSecond, 2, 2},
      {I::kFrexp, "frexp", R::kOutSecond, 2, 2},
      {I::kClip, "clip", R::kVoid, 1, 1},              {I::kBarrier, "barrier", R::kVoid, 0, 0},
      {I::kMemoryBarrier, "memoryBarrier", R::kVoid, 0, 0}, {I::kMemoryBarrier, "AllMemoryBarrier", R::kVoid, 0, 0},
      {I::kGroupMemoryBarrier, "groupMemoryBarrier", R::kVoid, 0, 0},
      {I::kGroupMemoryBarrier, "GroupMemoryBarrier", R::kVoid, 0, 0},
      {I::kGroupMemoryBarrierWithGroupSync, "GroupMemoryBarrierWithGroupSync", R::kVoid, 0, 0},
      {I::kTexGather, "tex2Dgather", R::kGather, 2, 3}, {I::kTexGatherR, "tex2DgatherR", R::kGather, 2, 3},
      {I::kTexGatherG, "tex2DgatherG", R::kGather, 2, 3}, {I::kTexGatherB, "tex2DgatherB", R::kGather, 2, 3},
      {I::kTexGatherA, "tex2DgatherA", R::kGather, 2, 3},
      {I::kAtomicAdd, "atomicAdd", R::kAtomic, 2, 3},  {I::kAtomicAnd, "atomicAnd", R::kAtomic, 2, 3},
      {I::kAtomicOr, "atomicOr", R::kAtomic, 2, 3},    {I::kAtomicXor, "atomicXor", R::kAtomic, 2, 3},
      {I::kAtomicMin, "atomicMin", R::kAtomic, 2, 3},  {I::kAtomicMax, "atomicMax", R::kAtomic, 2, 3},
      {I::kAtomicExchange, "atomicExchange", R::kAtomic, 2, 3},
      {I::kAtomicCompareExchange, "atomicCompareExchange", R::kAtomic, 3, 4},
  };
  // The texture forms, once per dimension (2D first, the spelling messages use).
  static const char* const kDimensions[] = {"tex2D", "tex1D", "tex3D"};
  static const struct {
    Intrinsic id;
    const char* suffix;
    IntrinsicRule rule;
    int min_arguments, max_arguments;
  } kForms[] = {
      {I::kTexSample, "", R::kSample, 2, 3},          {I::kTexSampleOffset, "offset", R::kSample, 3, 3},
      {I::kTexSampleLod, "lod", R::kSample, 2, 3},    {I::kTexSampleLodOffset, "lodoffset", R::kSample, 3, 3},
      {I::kTexSampleBias, "bias", R::kSample, 2, 3},  {I::kTexSampleProj, "proj", R::kSample, 2, 3},
      {I::kTexSampleGrad, "grad", R::kSample, 4, 5},  {I::kTexFetch, "fetch", R::kSample, 2, 3},
      {I::kTexSize, "size", R::kSize, 1, 2},          {I::kTexStore, "store", R::kStore, 3, 3},
  };
  for (const char* dimension : kDimensions)
    for (const auto& form : kForms)
      t.push_back({form.id, std::string(dimension) + form.suffix, form.rule, form.min_arguments, form.max_arguments});
  return t;
}

}  // namespace

const std::vector<IntrinsicInfo>& intrinsic_table() {
  static const std::vector<IntrinsicInfo> t = rows();
  return t;
}

const IntrinsicInfo* find_intrinsic(const std::string& name) {
  static const std::map<std::string, const IntrinsicInfo*> by_name = [] {
    std::map<std::string, const IntrinsicInfo*> m;
    for (const IntrinsicInfo& row : intrinsic_table()) m.emplace(row.name, &row);
    return m;
  }();
  auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : it->second;
}

const std::string& intrinsic_name(Intrinsic id) {
  static const std::string none;
  for (const IntrinsicInfo& row : intrinsic_table())
    if (row.id == id) return row.name;
  return none;
}

}  // namespace pfx::fx
