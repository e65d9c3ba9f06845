// Integer and bool matrices compute as integers, as HLSL's do: division truncates toward zero, %
// keeps the dividend's sign, sums past 2^24 stay exact and past 2^31 wrap, bit operators work,
// a float matrix converts by truncating each element; elements, rows and swizzles read and write
// them; an int matrix uniform arrives as its initial value. Every expected value is worked out by
// hand.
// size: 64x2
#include "include/check.fxh"

uniform int2x2 Table = int2x2(1, -2, 3, 40000000);

void Halve(inout float2x2 m) { m *= 0.5; }

bool Check(int i)
{
  int2x2 m = int2x2(7 + IZero, 2, -7, 3);  // rows (7, 2) and (-7, 3)
  switch (i)
  {
    case 0: { int2x2 d = m / 2; return d._m00 == 3 && d._m01 == 1 && d._m10 == -3 && d._m11 == 1; }
    case 1: { int2x2 r = m % 2; return r._m00 == 1 && r._m01 == 0 && r._m10 == -1 && r._m11 == 1; }
    case 2: { int2x2 big = int2x2(16777217 + IZero, 0, 0, 0x7FFFFFFF) + 1; return big._m00 == 16777218 && big._m11 == -2147483647 - 1; }
    case 3: { int2x2 b = (m & 6) | int2x2(8, 8, 0, 0); return b._m00 == 14 && b._m01 == 10 && b._m10 == 0 && b._m11 == 2; }  // -7 & 6 = 0
    case 4: { int2x2 s = (m << 2) ^ 1; int2x2 n = ~m; return s._m00 == 29 && s._m10 == -27 && n._m00 == -8 && n._m10 == 6; }
    case 5: { int2x2 t = (int2x2)(float2x2(1.5, -1.5, 2.9, -2.9) + Zero); return t._m00 == 1 && t._m01 == -1 && t._m10 == 2 && t._m11 == -2; }
    case 6: { float2x2 f = m; f *= 0.5; return f._m00 == 3.5 && f._m10 == -3.5; }
    case 7: { int2x2 a = m; a._m01 = 5; a[1] = int2(8, 9); a[0][0] += 3; return all(a[0] == int2(10, 5)) && all(a[1] == int2(8, 9)); }
    case 8: { int2x2 a = m; a._m00_m11 = int2(-1, -2); return a._m00 == -1 && a._m11 == -2 && a._m01 == 2; }
    case 9: { bool2x2 b = int2x2(0 + IZero, 3, 0, -1); bool2x2 n = !b; return !b._m00 && b._m01 && n._m00 && !n._m11; }
    case 10: { int2x2 a = m; Halve(a); return a._m00 == 3 && a._m10 == -3 && a._m01 == 1; }  // 3.5, -3.5, 1.0 truncated back
    case 11: return Table._m00 == 1 && Table._m01 == -2 && Table[1][0] == 3 && Table._m11 / 3 == 13333333;
    case 12: { int3x2 r = int3x2(int2(1, 2) + IZero, int2(3, 4), int2(5, 6)); return r._m21 == 6 && r[1][0] == 3 && all(r[2] == int2(5, 6)); }
    case 13: { int4 v = (int4)m; return all(v == int4(7, 2, -7, 3)); }
    case 14: { bool2x2 e = m == int2x2(7, 0, -7, 0); return e._m00 && !e._m01 && e._m10 && all(m == m); }
    case 15: { uint2x2 u = uint2x2(0u + uint(IZero), 5u, 7u, 9u) - 1u; return u._m00 == 4294967295u && u._m01 / 2u == 2u; }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique integer_matrices { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
