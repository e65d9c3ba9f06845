// Comparing matrices gives a matrix of bools, one per element, and all() and any() take a matrix
// (true when every, or some, element is not zero), as in HLSL. Every expected value is worked
// out by hand.
// size: 40x2
#include "include/check.fxh"

bool Check(int i)
{
  float2x2 a = float2x2(1, 2, 3, 4) + Zero;
  float2x2 b = float2x2(1, 5, 3, 0) + Zero;
  switch (i)
  {
    case 0: { bool2x2 e = a == b; return e._m00 && !e._m01 && e._m10 && !e._m11; }
    case 1: { bool2x2 n = a != b; return !n._m00 && n._m01 && !n._m10 && n._m11; }
    case 2: { bool2x2 l = a < b; return !l._m00 && l._m01 && !l._m10 && !l._m11; }
    case 3: return all(a == a) && !all(a == b) && any(a == b) && !any(a != a);
    case 4: return all(a) && !all(b) && any(b) && !any(a * Zero);
    case 5: { float2x3 c = float2x3(0, 0, 0, 0, 0, 1) + Zero; return any(c) && !all(c) && all(c >= 0.0); }
    case 6: { float2x2 f = (float2x2)(a >= b); return all(f[0] == float2(1, 0)) && all(f[1] == float2(1, 1)); }
    case 7: { int2x2 k = int2x2(0, 0, 0, -1); return any(k) && !all(k); }
    case 8: { float2x2 nan = float2x2(0, 0, 0, 0) + sqrt(-1.0 - Zero); return any(nan) && !any(nan == nan); }  // NaN is not zero and equals nothing
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique matrix_comparisons { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
