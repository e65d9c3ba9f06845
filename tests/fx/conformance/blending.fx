// Blend states: operations, factors, separate alpha, the write mask; each result worked out by hand
// from the two values a pass pair writes.
// size: 32x2
#include "include/check.fxh"

texture TAdd { Format = RGBA32F; };
texture TRev { Format = RGBA32F; };
texture TMinMax { Format = RGBA32F; };
texture TAlpha { Format = RGBA32F; };
texture TMask { Format = RGBA32F; };
sampler SAdd { Texture = TAdd; };
sampler SRev { Texture = TRev; };
sampler SMinMax { Texture = TMinMax; };
sampler SAlpha { Texture = TAlpha; };
sampler SMask { Texture = TMask; };

float4 First(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.25, 0.5, 0.75, 0.5); }
float4 Second(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return float4(0.5, 0.25, 0.125, 0.25); }
float4 Ones(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 1.0; }

float4 Fetch(sampler s) { return tex2Dfetch(s, int2(0, 0) + IZero); }

bool Check(int i)
{
  switch (i)
  {
    // ONE + ONE on colour; alpha keeps its defaults, SrcBlendAlpha ONE and DestBlendAlpha ZERO.
    case 0: return all(Fetch(SAdd) == float4(0.75, 0.75, 0.875, 0.25));
    case 1: return all(Fetch(SRev) == float4(-0.25, 0.25, 0.625, 0.25));     // dest - src
    case 2: return all(Fetch(SMinMax) == float4(0.25, 0.25, 0.125, 0.5));    // MIN on colour, MAX on alpha
    // SRCALPHA / INVSRCALPHA on colour: 0.25 src + 0.75 dest; alpha ZERO / ONE keeps the dest's.
    case 3: return all(Fetch(SAlpha) == float4(0.3125, 0.4375, 0.59375, 0.5));
    case 4: return all(Fetch(SMask) == float4(1.0, 0.5, 0.75, 1.0));         // red and alpha written only
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique blending
{
  pass { VertexShader = PostProcessVS; PixelShader = First; RenderTarget = TAdd; }
  pass { VertexShader = PostProcessVS; PixelShader = Second; RenderTarget = TAdd; BlendEnable = true; SrcBlend = ONE; DestBlend = ONE; }
  pass { VertexShader = PostProcessVS; PixelShader = First; RenderTarget = TRev; }
  pass { VertexShader = PostProcessVS; PixelShader = Second; RenderTarget = TRev; BlendEnable = true; BlendOp = REVSUBTRACT; BlendOpAlpha = SUBTRACT; SrcBlend = ONE; DestBlend = ONE; }
  pass { VertexShader = PostProcessVS; PixelShader = First; RenderTarget = TMinMax; }
  pass { VertexShader = PostProcessVS; PixelShader = Second; RenderTarget = TMinMax; BlendEnable = true; BlendOp = MIN; BlendOpAlpha = MAX; }
  pass { VertexShader = PostProcessVS; PixelShader = First; RenderTarget = TAlpha; }
  pass { VertexShader = PostProcessVS; PixelShader = Second; RenderTarget = TAlpha; BlendEnable = true; SrcBlend = SRCALPHA; DestBlend = INVSRCALPHA; SrcBlendAlpha = ZERO; DestBlendAlpha = ONE; }
  pass { VertexShader = PostProcessVS; PixelShader = First; RenderTarget = TMask; }
  pass { VertexShader = PostProcessVS; PixelShader = Ones; RenderTarget = TMask; RenderTargetWriteMask = 9; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
