// Storing to a swizzle of several matrix elements writes those elements and no others: plain and
// compound assignment, a chain of assignments (the value of an assignment is the value stored),
// a swizzle of the same matrix on the right, the _11 and _m00 spellings. Every expected value is
// worked out by hand.
// size: 40x2
#include "include/check.fxh"

bool Check(int i)
{
  float2x2 m = float2x2(1, 2, 3, 4) + Zero;  // rows (1, 2) and (3, 4)
  float3x3 z = 0.0 + Zero;
  switch (i)
  {
    case 0: { float3x3 a = z; a._m00_m11 = float2(5, 6) + Zero; return a._m00 == 5.0 && a._m11 == 6.0 && a._m22 == 0.0 && a._m01 == 0.0; }
    case 1: { float2x2 a = m; a._m01_m10 += float2(10, 20); return a._m01 == 12.0 && a._m10 == 23.0 && a._m00 == 1.0 && a._m11 == 4.0; }
    case 2: { float2x2 a = m; a._m00_m01 = a._m10_m11; return all(a[0] == float2(3, 4)) && all(a[1] == float2(3, 4)); }
    case 3: { float2x2 a = m; a._m00_m01 = a._m01_m00; return all(a[0] == float2(2, 1)); }  // read before written
    case 4: { float3x3 a = z; a._11_22_33 = float3(1, 2, 3) + Zero; return a[0][0] == 1.0 && a[1][1] == 2.0 && a[2][2] == 3.0 && a[2][0] == 0.0; }
    case 5: { float2x2 a = m; float2 v = (a._m10_m11 = float2(8, 9) + Zero); return all(v == float2(8, 9)) && a._m11 == 9.0; }
    case 6: { float2x2 a = m; a._m00_m11 *= 3.0; return a._m00 == 3.0 && a._m11 == 12.0 && a._m01 == 2.0; }
    case 7: { float2x2 a = m; a._m10_m01 = 7.0 + Zero; return a._m10 == 7.0 && a._m01 == 7.0 && a._m00 == 1.0; }  // a scalar to each
    case 8: { float2x2 a = m; a._m11_m00 = float2(5, 6) + Zero; return a._m11 == 5.0 && a._m00 == 6.0; }  // in the swizzle's order
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique matrix_swizzle_stores { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
