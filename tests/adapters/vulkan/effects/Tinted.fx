// What the layer's tests check a preset's preprocessor definitions with: TINT_AMOUNT, which the file
// defaults to 0 (the frame unchanged), moves the picture towards orange.
#include "ReShade.fxh"

#ifndef TINT_AMOUNT
#define TINT_AMOUNT 0.0
#endif

float4 Tinted(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 colour = tex2D(ReShade::BackBuffer, texcoord);
  return float4(lerp(colour.rgb, float3(1.0, 0.5, 0.0), TINT_AMOUNT), colour.a);
}

technique Tinted
{
  pass { VertexShader = PostProcessVS; PixelShader = Tinted; }
}
