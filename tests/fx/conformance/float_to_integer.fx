// A float converted to int or uint follows HLSL's rule (the ftoi and ftou instructions): toward
// zero, saturated at the type's range, NaN to 0, where GLSL leaves a value out of range undefined:
// uint(-1.0) is 0, uint(1e10) is 4294967295, int(-1e10) is -2147483648, int(NaN) is 0. The same
// holds in casts, implicit conversions, constructors, initialiser lists, matrices, and in the
// values the runtime works out on the CPU (a uniform's initial value). Every expected value is
// written out by hand.
// size: 64x2
#include "include/check.fxh"

uniform uint FromNegative = -2.5;
uniform int FromHuge = 3e9;
uniform uint FromHugeUnsigned = 5e9;

bool Check(int i)
{
  // From their bits: Vulkan leaves 0.0 / 0.0 and 1.0 / 0.0 undefined.
  float nan = asfloat(0x7FC00000u + uint(IZero)), inf = asfloat(0x7F800000u + uint(IZero));
  switch (i)
  {
    case 0: return uint(-1.0 + Zero) == 0u && uint(-0.5 + Zero) == 0u && uint(3.9 + Zero) == 3u;
    case 1: return (uint)(1e10 + Zero) == 4294967295u && (uint)(4294967040.0 + Zero) == 4294967040u;
    case 2: return int(-3.9 + Zero) == -3 && int(1e10 + Zero) == 2147483647 && int(-1e10 + Zero) == -2147483647 - 1;
    case 3: return int(nan) == 0 && uint(nan) == 0u && int(inf) == 2147483647 && int(-inf) == -2147483647 - 1 && uint(inf) == 4294967295u;
    case 4: { uint u = -2.0 + Zero; int k = 2.5e9 + Zero; return u == 0u && k == 2147483647; }  // implicit
    case 5: return all(uint2(float2(-1.0, 5.5) + Zero) == uint2(0, 5)) && all(int3(float3(-1e10, 7.9, nan) + Zero) == int3(-2147483647 - 1, 7, 0));
    case 6: { uint2 c = uint2(-1.0 + Zero, 2.0 + Zero); int2 d = int2(nan, -2.5 + Zero); return all(c == uint2(0, 2)) && all(d == int2(0, -2)); }
    case 7: { uint a[2] = { -1.0 + Zero, 7.5 + Zero }; return a[0] == 0u && a[1] == 7u; }
    case 8: { int2x2 m = (int2x2)(float2x2(-1e10, 1.5, -1.5, 1e10) + Zero); return m._m00 == -2147483647 - 1 && m._m01 == 1 && m._m10 == -1 && m._m11 == 2147483647; }
    case 9: return FromNegative == 0u && FromHuge == 2147483647 && FromHugeUnsigned == 4294967295u;
    case 10: { uint4 v = (uint4)(float4(-3.0, 0.0, 65535.9, -0.0) + Zero); return all(v == uint4(0, 0, 65535, 0)); }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique float_to_integer { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
