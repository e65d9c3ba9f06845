// Mip chains: GenerateMipMaps after a pass (each level the average of four texels of the one
// above), levels chosen with tex2Dlod and tex2Dfetch, the sampler's MinLOD, MaxLOD and
// MipLODBias, and a chain left alone with GenerateMipMaps = false.
// size: 32x2
#include "include/check.fxh"

texture Pyramid { Width = 4; Height = 4; MipLevels = 3; Format = RGBA32F; };
sampler PyramidPoint { Texture = Pyramid; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
sampler PyramidFloor { Texture = Pyramid; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; MinLOD = 2; };
sampler PyramidCeiling { Texture = Pyramid; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; MaxLOD = 0; };
sampler PyramidBias { Texture = Pyramid; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; MipLODBias = 1; };
texture Kept { Width = 2; Height = 2; MipLevels = 2; Format = R32F; };
sampler KeptPoint { Texture = Kept; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };

// Texel (x, y) from the top: x + 4 y. Level 1's texel (0, 0) is (0 + 1 + 4 + 5) / 4 = 2.5, its
// (1, 0) is (2 + 3 + 6 + 7) / 4 = 4.5; level 2 is the mean, 7.5.
float4 Fill(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float2 p = floor(position.xy);
  return p.x + 4.0 * p.y;
}
float4 FillKept(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 3.0; }

bool Check(int i)
{
  float2 uv = float2(0.125, 0.125) + Zero;  // texel (0, 0) of level 0
  switch (i)
  {
    case 0: return tex2Dlod(PyramidPoint, float4(uv, 0, 0)).x == 0.0 && tex2Dlod(PyramidPoint, float4(uv, 0, 1)).x == 2.5;
    case 1: return tex2Dlod(PyramidPoint, float4(uv, 0, 2)).x == 7.5;
    case 2: return tex2Dfetch(PyramidPoint, int2(1, 0) + IZero, 1).x == 4.5 && all(tex2Dsize(PyramidPoint, 1) == int2(2, 2));
    case 3: return tex2Dlod(PyramidFloor, float4(uv, 0, 0)).x == 7.5;     // MinLOD = 2
    case 4: return tex2Dlod(PyramidCeiling, float4(uv, 0, 2)).x == 0.0;   // MaxLOD = 0
    case 5: return tex2Dlod(PyramidBias, float4(uv, 0, 0)).x == 2.5;      // MipLODBias = 1
    case 6: return tex2Dfetch(KeptPoint, int2(0, 0) + IZero, 0).x == 3.0 && tex2Dfetch(KeptPoint, int2(0, 0) + IZero, 1).x == 0.0;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique mips
{
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = Pyramid; }
  pass { VertexShader = PostProcessVS; PixelShader = FillKept; RenderTarget = Kept; GenerateMipMaps = false; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
