// The texture intrinsics, with FX's origin at the top-left corner: fetch, lod, size, gather (and
// its per-channel forms, in HLSL's order), offset, grad, bias, proj; and the back buffer holding
// the input picture the right way up.
// size: 64x4
#include "include/check.fxh"
#include "include/input_picture.fxh"

texture Grid { Width = 8; Height = 4; Format = RGBA32F; };
sampler GridPoint { Texture = Grid; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
sampler GridLinear { Texture = Grid; };

// Texel (x, y) of Grid, counted from the top: (x, y, x + 10 y, 1).
float4 FillGrid(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float2 p = floor(position.xy);
  return float4(p.x, p.y, p.x + 10.0 * p.y, 1.0);
}

float2 Centre(int2 texel) { return (float2(texel) + 0.5) / float2(8.0, 4.0); }

bool Check(int i)
{
  float4 g;
  switch (i)
  {
    case 0: return all(tex2Dfetch(GridPoint, int2(3, 1) + IZero) == float4(3, 1, 13, 1));
    case 1: return all(tex2D(GridPoint, Centre(int2(5, 2)) + Zero) == float4(5, 2, 25, 1));
    case 2: return all(tex2Dlod(GridLinear, float4(Centre(int2(6, 3)), 0, 0) + Zero) == float4(6, 3, 36, 1));
    case 3: return all(tex2Dsize(GridPoint) == int2(8, 4)) && all(tex2Dsize(GridPoint, 0) == int2(8, 4));
    // The corner between texels (1, 1), (2, 1), (1, 2) and (2, 2): HLSL gathers (u0, v1), (u1, v1),
    // (u1, v0), (u0, v0) with v1 the lower row.
    case 4: g = tex2DgatherR(GridPoint, float2(2.0 / 8.0, 2.0 / 4.0) + Zero); return all(g == float4(1, 2, 2, 1));
    case 5: g = tex2DgatherG(GridPoint, float2(2.0 / 8.0, 2.0 / 4.0) + Zero); return all(g == float4(2, 2, 1, 1));
    case 6: g = tex2Dgather(GridPoint, float2(2.0 / 8.0, 2.0 / 4.0) + Zero); return all(g == float4(1, 2, 2, 1));
    case 7: return all(tex2Doffset(GridPoint, Centre(int2(2, 1)) + Zero, int2(1, 1)) == float4(3, 2, 23, 1));  // +y is down
    case 8: return all(tex2D(GridPoint, Centre(int2(2, 1)) + Zero, int2(-1, 2)) == float4(1, 3, 31, 1));
    case 9: return all(tex2Dgrad(GridPoint, Centre(int2(4, 0)) + Zero, float2(0, 0), float2(0, 0)) == float4(4, 0, 4, 1));
    case 10: return all(tex2Dbias(GridPoint, float4(Centre(int2(7, 3)), 0, 0) + Zero) == float4(7, 3, 37, 1));
    case 11: return all(tex2Dproj(GridPoint, float4(Centre(int2(1, 2)) * 2.0, 0, 2) + Zero) == float4(1, 2, 21, 1));
    case 12: return Near(tex2D(GridLinear, float2(2.0 / 8.0, 0.5 / 4.0) + Zero).x, 1.5);  // halfway between two texels
    // The back buffer is the input picture, its first row at the top.
    case 13: return SameCode(tex2Dfetch(ReShade::BackBuffer, int2(0, 0) + IZero).rgb, InputPixel(int2(0, 0)));
    case 14: return SameCode(tex2Dfetch(ReShade::BackBuffer, int2(5, 1) + IZero).rgb, InputPixel(int2(5, 1)));
    case 15: return SameCode(tex2D(ReShade::BackBuffer, (float2(9, 3) + 0.5) / float2(64, 4) + Zero).rgb, InputPixel(int2(9, 3)));
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  // SV_Position and TEXCOORD agree, both from the top-left corner.
  bool agree = all(abs(texcoord * float2(64, 4) - position.xy) < 0.01);
  return Verdict(agree && Check(CheckIndex(position)));
}

technique textures
{
  pass { VertexShader = PostProcessVS; PixelShader = FillGrid; RenderTarget = Grid; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
