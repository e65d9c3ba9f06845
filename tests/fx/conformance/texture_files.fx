// Textures that start from an image file (`source`): Textures/conformance_texels.png is 4x2 RGBA,
// written by hand: row 0 (10,20,30,255) (40,50,60,200) (70,80,90,150) (100,110,120,100), row 1
// (130,140,150,50) (160,170,180,25) (190,200,210,5) (220,230,240,0). The texels arrive top row
// first with their alpha, an image of another size is scaled to the texture's (nearest texel), a
// texture of another format takes the codes converted (R16F holds code / 255), a linear sampler
// between two texels averages them, and the mip levels are made from the image (level 1 of the
// 4x2 texture: each 2x2 block averaged).
// size: 48x1
#include "include/check.fxh"

texture TFile < source = "conformance_texels.png"; > { Width = 4; Height = 2; };
texture THalf < source = "conformance_texels.png"; > { Width = 2; Height = 1; };
texture TFloat < source = "conformance_texels.png"; > { Width = 4; Height = 2; Format = R16F; };
texture TMips < source = "conformance_texels.png"; > { Width = 4; Height = 2; MipLevels = 2; };
sampler SFile { Texture = TFile; MinFilter = POINT; MagFilter = POINT; };
sampler SLinear { Texture = TFile; };
sampler SHalf { Texture = THalf; };
sampler SFloat { Texture = TFloat; };
sampler SMips { Texture = TMips; };

bool Code(float4 seen, float4 codes) { return all(abs(seen * 255.0 - codes) <= 0.5); }
bool Within(float4 seen, float4 codes, float codes_off) { return all(abs(seen * 255.0 - codes) <= codes_off); }

bool Check(int i)
{
  int2 p = int2(IZero + i % 4, IZero + i / 4);
  switch (i)
  {
    case 0: return Code(tex2Dfetch(SFile, p), float4(10, 20, 30, 255));
    case 1: return Code(tex2Dfetch(SFile, p), float4(40, 50, 60, 200));
    case 2: return Code(tex2Dfetch(SFile, p), float4(70, 80, 90, 150));
    case 3: return Code(tex2Dfetch(SFile, p), float4(100, 110, 120, 100));
    case 4: return Code(tex2Dfetch(SFile, p), float4(130, 140, 150, 50));
    case 5: return Code(tex2Dfetch(SFile, p), float4(160, 170, 180, 25));
    case 6: return Code(tex2Dfetch(SFile, p), float4(190, 200, 210, 5));
    case 7: return Code(tex2Dfetch(SFile, p), float4(220, 230, 240, 0));
    case 8: return Code(tex2Dfetch(SHalf, int2(0, 0) + IZero), float4(10, 20, 30, 255)) &&
                   Code(tex2Dfetch(SHalf, int2(1, 0) + IZero), float4(70, 80, 90, 150));
    case 9: return abs(tex2Dfetch(SFloat, int2(3, 1) + IZero).x - 220.0 / 255.0) <= 1e-3;
    // Halfway between the centres of texels (0, 0) and (1, 0) of the top row.
    case 10: return Within(tex2Dlod(SLinear, float4(0.25, 0.25, 0.0, 0.0)), float4(25, 35, 45, 227.5), 1.0);
    // Level 1 texel (0, 0): the block (10, 40, 130, 160) in red, and so on.
    case 11: return Within(tex2Dlod(SMips, float4(0.25, 0.5, 0.0, 1.0)), float4(85, 95, 105, 132.5), 1.0);
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique texture_files { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
