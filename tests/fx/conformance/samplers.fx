// Every sampler state: address modes (CLAMP, WRAP, MIRROR, BORDER) outside [0, 1], POINT and
// LINEAR filtering, SRGBTexture decoding and SRGBWriteEnable encoding.
// size: 48x2
#include "include/check.fxh"

texture Row { Width = 4; Height = 1; Format = R32F; };  // 10, 20, 30, 40
sampler RowClamp { Texture = Row; AddressU = CLAMP; MinFilter = POINT; MagFilter = POINT; };
sampler RowWrap { Texture = Row; AddressU = WRAP; MinFilter = POINT; MagFilter = POINT; };
sampler RowMirror { Texture = Row; AddressU = MIRROR; MinFilter = POINT; MagFilter = POINT; };
sampler RowBorder { Texture = Row; AddressU = BORDER; MinFilter = POINT; MagFilter = POINT; };
sampler RowLinear { Texture = Row; MinFilter = LINEAR; MagFilter = LINEAR; };

texture Encoded { Width = 1; Height = 1; Format = RGBA8; };
sampler EncodedRaw { Texture = Encoded; };
sampler EncodedSrgb { Texture = Encoded; SRGBTexture = true; };
texture Written { Width = 1; Height = 1; Format = RGBA8; };
sampler WrittenRaw { Texture = Written; };

float4 FillRow(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return (floor(position.x) + 1.0) * 10.0;
}
float4 FillEncoded(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 0.5; }
// Linear 0.2158605 is sRGB code 128 (0.5 encoded rounds to it).
float4 FillWritten(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 0.2158605; }

float At(sampler s, float u) { return tex2D(s, float2(u, 0.5) + Zero).x; }

bool Check(int i)
{
  switch (i)
  {
    case 0: return At(RowClamp, -0.5) == 10.0 && At(RowClamp, 1.5) == 40.0;
    case 1: return At(RowWrap, 1.125) == 10.0 && At(RowWrap, -0.125) == 40.0;
    case 2: return At(RowMirror, 1.125) == 40.0 && At(RowMirror, -0.125) == 10.0;
    case 3: return At(RowBorder, -0.5) == 0.0 && At(RowBorder, 0.125) == 10.0;  // transparent black
    case 4: return Near(At(RowLinear, 0.25), 15.0) && At(RowClamp, 0.3) == 20.0;
    case 5: return Near(tex2D(EncodedRaw, 0.5 + Zero).x, 128.0 / 255.0);
    // Decoded on sampling; GPUs decode to a few parts in 10000 (Mesa with a polynomial).
    case 6: return abs(tex2D(EncodedSrgb, 0.5 + Zero).x - 0.2158605) < 1.0 / 1024.0;
    case 7: return Near(tex2D(WrittenRaw, 0.5 + Zero).x, 128.0 / 255.0);      // encoded on writing
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique samplers
{
  pass { VertexShader = PostProcessVS; PixelShader = FillRow; RenderTarget = Row; }
  pass { VertexShader = PostProcessVS; PixelShader = FillEncoded; RenderTarget = Encoded; }
  pass { VertexShader = PostProcessVS; PixelShader = FillWritten; RenderTarget = Written; SRGBWriteEnable = true; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
