// HLSL's implicit conversions: vector truncation, scalar splat, int/uint/float/bool both ways
// (float to int truncates toward zero), in declarations, arguments, returns and operators.
// size: 48x2
#include "include/check.fxh"

float TakesFloat(float x) { return x; }
int TakesInt(int x) { return x; }
float2 ReturnsTruncated() { return float4(1, 2, 3, 4) + Zero; }

bool Check(int i)
{
  switch (i)
  {
    case 0: { float2 t = float4(1, 2, 3, 4) + Zero; return all(t == float2(1, 2)); }
    case 1: { float4 s = 2.0 + Zero; return all(s == float4(2, 2, 2, 2)); }
    case 2: { int a = 2.7 + Zero; int b = -2.7 + Zero; return a == 2 && b == -2; }
    case 3: { uint u = 3.9 + Zero; return u == 3u; }
    case 4: { bool b = 0.5 + Zero; bool z = Zero; return b && !z; }
    case 5: { float f = (true && Zero == 0.0); int k = (Zero == 0.0); return f == 1.0 && k == 1; }
    case 6: return TakesFloat(3 + IZero) == 3.0 && TakesInt(3.9 + Zero) == 3;
    case 7: return all(ReturnsTruncated() == float2(1, 2));
    case 8: { float3 v = float3(1, 2, 3) + IZero; return all(v * 2 == float3(2, 4, 6)); }  // int splat in an operator
    case 9: { int2 v = float2(-1.5, 2.5) + Zero; return all(v == int2(-1, 2)); }
    case 10: { uint u = -1 + IZero; return u == 0xFFFFFFFFu; }
    case 11: { float4 v = float3(1, 2, 3).xyzz + Zero; float x = v; return x == 1.0; }  // to a scalar: the first component
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique conversions { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
