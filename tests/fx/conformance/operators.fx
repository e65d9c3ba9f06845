// Operators with HLSL's precedence and meaning: integer division and remainder truncate toward
// zero, '%' works on floats, comparisons and logic work per component on vectors, '?:' picks per
// component with a vector condition.
// size: 64x2
#include "include/check.fxh"

bool Check(int i)
{
  int n = -7 + IZero;
  switch (i)
  {
    case 0: return n / 2 == -3 && n % 2 == -1 && (7 + IZero) % -2 == 1;
    case 1: return Near((-5.5 + Zero) % 2.0, -1.5) && Near((5.5 + Zero) % -2.0, 1.5);
    case 2: return 2 + 3 * 4 + IZero == 14 && (1 << 2 + 1 + IZero) == 8 && ((6 & 3 | 8) + IZero) == 10;
    case 3: return ((true + IZero) ? 2 : 3 + 1) == 2 && -2 * -3 + IZero == 6 && !(1 + IZero > 2);
    case 4: return all((float2(1, 3) + Zero < float2(2, 2)) == bool2(true, false));
    case 5: return all((bool2(true, false) && bool2(true, true)) == bool2(true, false)) && all((bool2(true, false) || bool2(false, false)) == bool2(true, false));
    case 6: return all(((float2(1, -1) + Zero > 0) ? float2(10, 10) : float2(20, 20)) == float2(10, 20));
    case 7: { int a = 5 + IZero; a += 3; a *= 2; a -= 1; a /= 3; if (a != 5) return false; a %= 3; a <<= 2; a |= 1; return a == 9; }
    case 8: { int b = 1 + IZero; b++; ++b; b--; return b == 2 && -b == -2; }
    case 9: { float f = 1.5 + Zero; f *= 2.0; f -= 0.5; f /= 2.0; return f == 1.25; }
    case 10: { float x = 2.0 + Zero; float4 v = float4(1, 2, 3, 4) + Zero; return all(x.xxx == float3(2, 2, 2)) && v.wzyx.x == 4.0 && v.ar.y == 1.0 && all(v.bg == float2(3, 2)); }
    case 11: { float4 v = float4(1, 2, 3, 4) + Zero; v.yx = v.xy; v.w = 9; return all(v == float4(2, 1, 3, 9)); }
    case 12: return all(!bool2(true, false) == bool2(false, true)) && all(-float2(1, -2) + Zero == float2(-1, 2));
    case 13: return (uint(7 + IZero) / 2u) == 3u && (uint(7 + IZero) % 4u) == 3u;
    case 14: { int s = 0; for (int k = 0; k < 10; ++k) { if (k == 2) continue; if (k == 6) break; s += k; } return s == 13 + IZero; }
    case 15: { int s = 0 + IZero, k = 0; while (k < 4) s += k++; do { s *= 2; } while (s < 0); return s == 12; }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique operators { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
