// static consts in namespaces whose values feed other constants, as filmic tone curves write them
// (A..F, a white scale, a Pi from acos): some fold at compile time, some depend on a uniform and
// are computed when the shader runs; each must hold its value wherever it is read, from nested
// namespaces, functions and arrays. Expected values worked out by hand (python for the digits).
// size: 32x2
#include "include/check.fxh"

namespace Filmic
{
  static const float A = 0.15 + Zero;  // a uniform in it: computed when the shader runs
  static const float B = A + 0.35;
  static const float W = 4.0;
  static const float WhiteScale = 1.0 / (W * (A * W + B));  // 1 / (4 * 1.1) = 0.2272727
  static const float Folded = 0.25 * 4.0;                   // constant: folded
  namespace Inner
  {
    static const float Pi = acos(-1.0);
    static const float TwoPi = 2.0 * Pi;
  }
  static const float Table[3] = { A, B, Inner::Pi };
  float3 Curve(float3 x) { return x * (A * x + B) * WhiteScale; }
}

bool Check(int i)
{
  switch (i)
  {
    case 0: return Near(Filmic::A, 0.15) && Near(Filmic::B, 0.5) && Near(Filmic::Folded + Zero, 1.0);
    case 1: return Near(Filmic::WhiteScale, 0.22727273);
    case 2: return Close(Filmic::Inner::Pi + Zero, 3.14159265) && Close(Filmic::Inner::TwoPi + Zero, 6.28318531);
    case 3: return Near(Filmic::Curve(float3(0.5, 0.5, 0.5) + Zero).r, 0.06534091);
    case 4: return Near(Filmic::Table[0], 0.15) && Near(Filmic::Table[1 + IZero], 0.5) && Close(Filmic::Table[2], 3.14159265);
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique namespaced_constants
{
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
