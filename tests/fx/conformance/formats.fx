// Every texture format: a pass writes a value (chosen away from rounding ties) into a texture of
// each format, and the last pass reads each back against what the format stores, worked out by
// hand: 8- and 16-bit normalised values rounded to the nearest code, halves to 11 bits.
// size: 64x2
#include "include/check.fxh"

texture TR8 { Format = R8; };  // 1x1
sampler SR8 { Texture = TR8; MinFilter = POINT; MagFilter = POINT; };
float4 WriteR8(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 0.2; }
texture TR16 { Format = R16; };  // 1x1
sampler SR16 { Texture = TR16; MinFilter = POINT; MagFilter = POINT; };
float4 WriteR16(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 0.25; }
texture TR16F { Format = R16F; };  // 1x1
sampler SR16F { Texture = TR16F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteR16F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 1.0 / 3.0; }
texture TR32F { Format = R32F; };  // 1x1
sampler SR32F { Texture = TR32F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteR32F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 1.0 / 3.0; }
texture TRG8 { Format = RG8; };  // 1x1
sampler SRG8 { Texture = TRG8; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRG8(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.25, 0.75, 0, 0); }
texture TRG16 { Format = RG16; };  // 1x1
sampler SRG16 { Texture = TRG16; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRG16(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.25, 0.125, 0, 0); }
texture TRG16F { Format = RG16F; };  // 1x1
sampler SRG16F { Texture = TRG16F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRG16F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(1.0 / 3.0, -2.5, 0, 0); }
texture TRG32F { Format = RG32F; };  // 1x1
sampler SRG32F { Texture = TRG32F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRG32F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(1.0 / 3.0, -1e10, 0, 0); }
texture TRGBA8 { Format = RGBA8; };  // 1x1
sampler SRGBA8 { Texture = TRGBA8; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRGBA8(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.2, 0.4, 0.6, 0.8); }
texture TRGBA16 { Format = RGBA16; };  // 1x1
sampler SRGBA16 { Texture = TRGBA16; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRGBA16(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.25, 0.125, 0.0625, 1.0); }
texture TRGBA16F { Format = RGBA16F; };  // 1x1
sampler SRGBA16F { Texture = TRGBA16F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRGBA16F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(65504.0, -0.5, 1.0 / 3.0, 2.0); }
texture TRGBA32F { Format = RGBA32F; };  // 1x1
sampler SRGBA32F { Texture = TRGBA32F; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRGBA32F(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(1e20, -1e-20, 1.0 / 3.0, 7.0); }
texture TRGB10A2 { Format = RGB10A2; };  // 1x1
sampler SRGB10A2 { Texture = TRGB10A2; MinFilter = POINT; MagFilter = POINT; };
float4 WriteRGB10A2(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.25, 0.125, 1.0, 0.7); }
texture TR32I { Format = R32I; };
sampler2D<int> SR32I { Texture = TR32I; };
int4 WriteR32I(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return -123456; }
texture TR32U { Format = R32U; };
sampler2D<uint> SR32U { Texture = TR32U; };
uint4 WriteR32U(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 4000000000u; }

bool Check(int i)
{
  float4 v;
  switch (i)
  {
    case 0: v = tex2Dfetch(SR8, int2(0, 0) + IZero); return Near(v.x, 51.0 / 255.0);
    case 1: v = tex2Dfetch(SR16, int2(0, 0) + IZero); return Near(v.x, 16384.0 / 65535.0);
    case 2: v = tex2Dfetch(SR16F, int2(0, 0) + IZero); return v.x == 0.333251953125;
    case 3: v = tex2Dfetch(SR32F, int2(0, 0) + IZero); return v.x == 1.0 / 3.0;
    case 4: v = tex2Dfetch(SRG8, int2(0, 0) + IZero); return Near(v.xy, float2(64.0, 191.0) / 255.0);
    case 5: v = tex2Dfetch(SRG16, int2(0, 0) + IZero); return Near(v.xy, float2(16384.0, 8192.0) / 65535.0);
    case 6: v = tex2Dfetch(SRG16F, int2(0, 0) + IZero); return all(v.xy == float2(0.333251953125, -2.5));
    case 7: v = tex2Dfetch(SRG32F, int2(0, 0) + IZero); return all(v.xy == float2(1.0 / 3.0, -1e10));
    case 8: v = tex2Dfetch(SRGBA8, int2(0, 0) + IZero); return Near(v, float4(51, 102, 153, 204) / 255.0);
    case 9: v = tex2Dfetch(SRGBA16, int2(0, 0) + IZero); return Near(v, float4(16384.0, 8192.0, 4096.0, 65535.0) / 65535.0);
    case 10: v = tex2Dfetch(SRGBA16F, int2(0, 0) + IZero); return all(v == float4(65504.0, -0.5, 0.333251953125, 2.0));
    case 11: v = tex2Dfetch(SRGBA32F, int2(0, 0) + IZero); return all(v == float4(1e20, -1e-20, 1.0 / 3.0, 7.0));
    case 12: v = tex2Dfetch(SRGB10A2, int2(0, 0) + IZero); return Near(v, float4(256.0 / 1023.0, 128.0 / 1023.0, 1.0, 2.0 / 3.0));
    case 13: return tex2Dfetch(SR32I, int2(0, 0) + IZero) == -123456;
    case 14: return tex2Dfetch(SR32U, int2(0, 0) + IZero) == 4000000000u;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique formats
{
  pass { VertexShader = PostProcessVS; PixelShader = WriteR8; RenderTarget = TR8; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteR16; RenderTarget = TR16; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteR16F; RenderTarget = TR16F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteR32F; RenderTarget = TR32F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRG8; RenderTarget = TRG8; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRG16; RenderTarget = TRG16; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRG16F; RenderTarget = TRG16F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRG32F; RenderTarget = TRG32F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRGBA8; RenderTarget = TRGBA8; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRGBA16; RenderTarget = TRGBA16; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRGBA16F; RenderTarget = TRGBA16F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRGBA32F; RenderTarget = TRGBA32F; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteRGB10A2; RenderTarget = TRGB10A2; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteR32I; RenderTarget = TR32I; }
  pass { VertexShader = PostProcessVS; PixelShader = WriteR32U; RenderTarget = TR32U; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
