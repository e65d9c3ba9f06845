// Matrices with HLSL's layout: rows first in constructors and indexing, mul() in both orders,
// '*' per component, non-square shapes, swizzles like _m01 and _11, truncation.
// size: 48x2
#include "include/check.fxh"

bool Check(int i)
{
  float2x2 a = float2x2(1, 2, 3, 4) + Zero;  // rows (1, 2) and (3, 4)
  float2x2 b = float2x2(5, 6, 7, 8) + Zero;
  float3x2 n = float3x2(1, 2, 3, 4, 5, 6) + Zero;  // three rows of two
  switch (i)
  {
    case 0: return a[1][0] == 3.0 && a[0][1] == 2.0 && all(a[1] == float2(3, 4));
    case 1: return all(mul(float2(1, 2), a) == float2(7, 10));   // row vector times matrix
    case 2: return all(mul(a, float2(1, 2)) == float2(5, 11));   // matrix times column vector
    case 3: { float2x2 c = mul(a, b); return c[0][0] == 19.0 && c[0][1] == 22.0 && c[1][0] == 43.0 && c[1][1] == 50.0; }
    case 4: { float2x2 c = a * b; return c[0][1] == 12.0 && c[1][1] == 32.0; }  // per component
    case 5: return n[2][1] == 6.0 && n._m11 == 4.0 && n._32 == 6.0 && n._11 == 1.0;
    case 6: return all(mul(float3(1, 1, 1), n) == float2(9, 12));
    case 7: { float2x3 t = transpose(n); return t[1][2] == 6.0 && t[0][1] == 3.0; }
    case 8: return determinant(a) == -2.0;
    case 9: { float4x4 m = float4x4(1,2,3,4, 5,6,7,8, 9,10,11,12, 13,14,15,16) + Zero; float3x3 s = (float3x3)m; return s[2][2] == 11.0 && s[1][0] == 5.0; }
    case 10: { float2x2 s = 2.0 + Zero; return s[0][1] == 2.0 && s[1][0] == 2.0; }  // a scalar fills every component
    case 11: { float4 v = float4(a); return all(v == float4(1, 2, 3, 4)); }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique matrices { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
