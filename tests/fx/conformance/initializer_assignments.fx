// A braced list as the value of an assignment, not only of a declaration, as ReShade takes it and
// public effects write it (SideWindows[0].Masks = { 1, 1, 1, 1, 1, 0, 1, 0, 0 };): into an array,
// an array member of a struct in an array, a struct, and a float2 array from a flat list (HLSL
// fills nested values in order). The values come from the lists themselves, read by eye; Zero and
// IZero keep them from being folded at compile time.
// size: 32x2
#include "include/check.fxh"

struct Window { int Masks[9]; float2 Centre; };
struct Pair { float a; int b; };

bool Check(int i)
{
  Window windows[2];
  windows[0].Masks = { 1, 1, 1, 1, 1, 0, 1, 0, 0 };
  windows[1].Masks = { 0, 0, 0, 0, 0, 0, 0, 0, 9 + IZero };
  windows[1].Centre = float2(0.0, 0.0);
  float weights[3];
  weights = { 0.5 + Zero, 0.25, 1 };  // the int 1 converted to float
  float2 corners[2];
  corners = { 1.0, 2.0, 3.0 + Zero, 4.0 };
  Pair pair;
  pair = { 0.75, 3 };
  switch (i)
  {
    case 0: return windows[0].Masks[4] == 1 && windows[0].Masks[5] == 0 && windows[0].Masks[6] == 1 && windows[0].Masks[8] == 0;
    case 1: return windows[1].Masks[8] == 9 && windows[1].Masks[0] == 0;
    case 2: return Near(weights[0], 0.5) && Near(weights[1], 0.25) && Near(weights[2], 1.0);
    case 3: return Near(corners[0], float2(1.0, 2.0)) && Near(corners[1], float2(3.0, 4.0));
    case 4: return Near(pair.a, 0.75) && pair.b == 3;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique initializer_assignments
{
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
