// What the layer's tests check an effect that reads depth with: ReShade's linearised depth hazes
// the picture, nothing at the near plane and Strength of the haze at the far one, which is what
// an application's frame without depth reads everywhere.
#include "ReShade.fxh"

uniform float Strength < ui_type = "slider"; ui_min = 0.0; ui_max = 1.0; > = 0.6;

float4 Haze(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 colour = tex2D(ReShade::BackBuffer, texcoord);
  float depth = ReShade::GetLinearizedDepth(texcoord);
  return float4(lerp(colour.rgb, float3(0.7, 0.75, 0.8), depth * Strength), colour.a);
}

technique Haze
{
  pass { VertexShader = PostProcessVS; PixelShader = Haze; }
}
