// What GLSL takes only as constants and HLSL takes from any expression: texel offsets of
// tex2Doffset and tex2Dlodoffset that the shader computes (they move the coordinate instead) or
// that name a static const, and switch case labels that name static consts, for an int and a uint
// selector. A 4x4 R32F grid holds (x + 4y) / 16 at texel (x, y), row 0 at the top.
// size: 64x2
#include "include/check.fxh"

texture2D GridTex { Width = 4; Height = 4; Format = R32F; };
sampler2D Grid { Texture = GridTex; MagFilter = POINT; MinFilter = POINT; MipFilter = POINT; };

static const int2 Shift = int2(-1, 1);
static const int ModeA = 3;
static const int ModeB = ModeA + 4;
static const uint Flag = 5u;

float4 Fill(float4 position : SV_Position) : SV_Target
{
  return float((int(position.x) + 4 * int(position.y))) / 16.0;
}

float2 Center(int x, int y) { return (float2(x, y) + 0.5) / 4.0; }

int Pick(int mode)
{
  switch (mode)
  {
    case ModeA: return 10;
    case ModeB: return 20;
    default: return 30;
  }
}

int PickUnsigned(uint value)
{
  switch (value)
  {
    case Flag: return 1;
    case Flag + 1u: return 2;
    default: return 0;
  }
}

bool Check(int i)
{
  switch (i)
  {
    case 0: return Near(tex2Doffset(Grid, Center(1, 1), int2(1, 2)).r, 14.0 / 16.0);
    case 1: return Near(tex2Doffset(Grid, Center(1, 1), int2(1 + IZero, 2 - IZero)).r, 14.0 / 16.0);
    case 2: return Near(tex2Doffset(Grid, Center(2, 1), Shift).r, 9.0 / 16.0);
    case 3: return Near(tex2Dlodoffset(Grid, float4(Center(0, 0), 0, 0), int2(3, 3) + IZero).r, 15.0 / 16.0);
    case 4: return Near(tex2Doffset(Grid, Center(3, 0), int2(-3 - IZero, 1)).r, 4.0 / 16.0);
    case 5: return Pick(3 + IZero) == 10 && Pick(7 + IZero) == 20 && Pick(IZero) == 30;
    case 6: return PickUnsigned(uint(5 + IZero)) == 1 && PickUnsigned(uint(6 + IZero)) == 2 && PickUnsigned(uint(IZero)) == 0;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique offsets_and_labels
{
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = GridTex; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
