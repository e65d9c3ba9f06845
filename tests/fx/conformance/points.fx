// A pass that draws points (PrimitiveTopology = POINTLIST): three points at the centres of texels
// 1, 3 and 5 of an 8x1 target cleared first cover exactly those texels, one each; the others stay 0.
// size: 32x1
#include "include/check.fxh"

texture TPoints { Width = 8; Height = 1; Format = R8; };
sampler SPoints { Texture = TPoints; MinFilter = POINT; MagFilter = POINT; };

void PointVS(uint id : SV_VertexID, out float4 position : SV_Position)
{
  // Texel 2 * id + 1 spans [2 id + 1, 2 id + 2) of 8: its centre is (2 id + 1.5) / 8 across.
  float x = (2.0 * id + 1.5) / 8.0;
  position = float4(x * 2.0 - 1.0, 0.0, 0.0, 1.0);
}

float4 PointPS(float4 position : SV_Position) : SV_Target { return 1.0; }

bool Check(int i)
{
  float seen = tex2Dfetch(SPoints, int2(i + IZero, 0)).x;
  return i == 1 || i == 3 || i == 5 ? seen == 1.0 : seen == 0.0;
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique points
{
  pass
  {
    VertexShader = PointVS;
    PixelShader = PointPS;
    PrimitiveTopology = POINTLIST;
    VertexCount = 3;
    RenderTarget = TPoints;
    ClearRenderTargets = true;
  }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
