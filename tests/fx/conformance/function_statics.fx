// A function's static variable keeps its value from one call to the next within a shader
// invocation, starting from its initialiser (or zero); two functions' statics of one name are
// two variables; a static const stays a constant. Every expected value is worked out by hand.
// size: 32x2
#include "include/check.fxh"

float Count() { static float n = 10.0; n += 1.0; return n; }
float CountOther() { static float n; n += 2.0; return n; }
int History(int x) { static int last[2] = { 0, 0 }; int before = last[0]; last[0] = last[1]; last[1] = x; return before; }
float Weight(int k) { static const float w[3] = { 0.25, 0.5, 0.25 }; return w[k]; }
float Accumulate(float x)
{
  static float total = 0.0;
  for (int i = 0; i < 3; ++i) { static float inner = 1.0; inner *= 2.0; total += x * inner; }
  return total;
}

bool Check(int i)
{
  switch (i)
  {
    case 0: { float a = Count(); float b = Count(); return a == 11.0 && b == 12.0; }
    case 1: { float a = Count(); float b = CountOther(); float c = CountOther(); return a == 11.0 && b == 2.0 && c == 4.0; }
    case 2: { History(5 + IZero); History(6); History(7); return History(8) == 6; }
    case 3: return Weight(1 + IZero) + Weight(0) + Weight(2) == 1.0;
    case 4: { float a = Accumulate(1.0 + Zero); float b = Accumulate(1.0); return a == 14.0 && b == 14.0 + 112.0; }  // 2+4+8, then 16+32+64
    case 5: { float a = Count(); for (int k = IZero; k < 4; ++k) a = Count(); return a == 15.0; }
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique function_statics { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
