#pragma once
// The intrinsic functions FX shaders call (HLSL's and ReShade's), in one table: each has an id,
// the names that spell it (tex1D, tex2D and tex3D are one sampling operation on the sampler's
// dimension; AllMemoryBarrier is memoryBarrier), how a call to it is typed and how many arguments
// it takes. Semantic analysis types a call from the table (sema/intrinsics.cpp) and records the
// id on the call; each back end switches over the ids, so one that misses an intrinsic does not
// compile (codegen/glsl_intrinsics.cpp).
#include <string>
#include <vector>

namespace pfx::fx {

enum class Intrinsic : unsigned char {
  kNone,
  // Component-wise float functions.
  kAcos, kAsin, kAtan, kCos, kCosh, kSin, kSinh, kTan, kTanh, kExp, kExp2, kLog, kLog2, kLog10, kSqrt, kRsqrt,
  kRcp, kCeil, kFloor, kFrac, kRound, kTrunc, kSaturate, kDegrees, kRadians, kDdx, kDdy, kDdxCoarse, kDdyCoarse,
  kDdxFine, kDdyFine, kFwidth, kNormalize, kPow, kAtan2, kFmod, kStep, kLdexp, kReflect, kLerp, kSmoothstep,
  kRefract, kFaceforward,
  // Component-wise on any number.
  kAbs, kMin, kMax, kClamp, kMad,
  // Classification, bits and reinterpretation.
  kIsnan, kIsinf, kIsfinite, kSign, kCountbits, kReversebits, kFirstbithigh, kFirstbitlow, kAsfloat, kAsint,
  kAsuint, kF16tof32, kF32tof16,
  // Vectors and matrices.
  kDot, kDistance, kLength, kDeterminant, kCross, kTranspose, kMul, kAll, kAny,
  // Results through out arguments.
  kSincos, kModf, kFrexp,
  // Discarding and synchronisation.
  kClip, kBarrier, kMemoryBarrier, kGroupMemoryBarrier, kGroupMemoryBarrierWithGroupSync,
  // Textures and storages (the dimension is the object's).
  kTexSample, kTexSampleOffset, kTexSampleLod, kTexSampleLodOffset, kTexSampleBias, kTexSampleProj, kTexSampleGrad,
  kTexFetch, kTexSize, kTexStore, kTexGather, kTexGatherR, kTexGatherG, kTexGatherB, kTexGatherA,
  // Atomic operations on storages and group-shared variables.
  kAtomicAdd, kAtomicAnd, kAtomicOr, kAtomicXor, kAtomicMin, kAtomicMax, kAtomicExchange, kAtomicCompareExchange,
  kCount
};

// How a call is typed (sema/intrinsics.cpp).
enum class IntrinsicRule : unsigned char {
  kFloatWise,    // float result, shape of the widest argument (sin, lerp, pow, saturate ...)
  kNumberWise,   // like kFloatWise but integers stay integers (abs, min, max, clamp, mad)
  kBoolWise,     // isnan, isinf: bool with the argument's shape
  kIntWise,      // sign: int with the argument's shape
  kUintWise,     // countbits, reversebits, firstbit*: uint with the argument's shape
  kAsFloat, kAsInt, kAsUint,  // reinterpretation, same shape
  kHalfToFloat, kFloatToHalf,
  kScalarFloat,  // dot, length, distance, determinant
  kCross, kTranspose, kMul, kAllAny,
  kSinCos, kOutSecond,  // sincos(x, out s, out c); modf/frexp(x, out i)
  kVoid,         // clip, barriers
  kSample,       // tex*D*: the sampler's element type
  kSize,         // tex*Dsize: int of the object's dimension
  kGather,       // tex2Dgather*: four of the element's base
  kStore,        // tex*Dstore: void
  kAtomic,       // atomic*: int (or the storage's element base)
};

struct IntrinsicInfo {
  Intrinsic id;
  std::string name;  // one spelling; an id may have several rows
  IntrinsicRule rule;
  int min_arguments;
  int max_arguments;
};

// Every row, one per spelling.
const std::vector<IntrinsicInfo>& intrinsic_table();

// The row of the intrinsic spelled `name`, or null.
const IntrinsicInfo* find_intrinsic(const std::string& name);

// The first spelling of `id` ("tex2D" for kTexSample), for messages.
const std::string& intrinsic_name(Intrinsic id);

}  // namespace pfx::fx
