// An out or inout argument whose type differs from its parameter's converts in and out, as HLSL
// does: an int variable given to a float parameter reads back truncated toward zero, a float
// given to an int parameter arrives truncated, a float4 given to a float parameter keeps its
// other components; a matrix element or a matrix swizzle can be the argument; a function that
// returns a value still returns it. Every expected value is worked out by hand.
// size: 48x2
#include "include/check.fxh"

void SetHalves(out float x) { x = 2.5 + Zero; }
void Double(inout float x) { x = x * 2.0; }
void Negate(inout int x) { x = -x; }
float IncrementAndOld(inout float x) { float old = x; x += 1.75; return old; }
void SetPair(out float2 p) { p = float2(7.0, 8.0) + Zero; }
void Swap(inout float a, inout float b) { float t = a; a = b; b = t; }

bool Check(int i)
{
  float2x2 m = float2x2(1, 2, 3, 4) + Zero;
  switch (i)
  {
    case 0: { int k = 3 + IZero; SetHalves(k); return k == 2; }
    case 1: { int k = -3 + IZero; Double(k); return k == -6; }
    case 2: { float f = 2.75 + Zero; Negate(f); return f == -2.0; }  // 2.75 arrives as 2
    case 3: { uint u = 5u + uint(IZero); float old = IncrementAndOld(u); return old == 5.0 && u == 6u; }
    case 4: { float f = 1.5 + Zero; float old = IncrementAndOld(f); return old == 1.5 && f == 3.25; }
    case 5: { float2x2 a = m; SetHalves(a._m11); return a._m11 == 2.5 && a._m10 == 3.0; }
    case 6: { float2x2 a = m; SetPair(a._m01_m10); return a._m01 == 7.0 && a._m10 == 8.0 && a._m00 == 1.0 && a._m11 == 4.0; }
    case 7: { float2x2 a = m; Swap(a._m00, a._m11); return a._m00 == 4.0 && a._m11 == 1.0; }
    case 8: { int2 v = int2(3, 9) + IZero; Double(v.y); return v.x == 3 && v.y == 18; }
    case 9: { bool b = IZero == 0; Double(b); return b; }  // true arrives as 1.0 and 2.0 converts back to true
    case 10: { float r = IncrementAndOld(m._m00) + IncrementAndOld(m._m00); return r == 3.75 && m._m00 == 4.5; }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique out_arguments { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
