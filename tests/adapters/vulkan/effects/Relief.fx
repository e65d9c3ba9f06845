// What the layer's native path is checked with in vkcube: two passes through a texture of the
// effect's own, the texels above and below each pixel (a frame turned upside down would change
// the relief's sign) and a parameter the test sets.
#include "ReShade.fxh"

uniform float Strength < ui_type = "slider"; ui_min = 0.0; ui_max = 4.0; > = 1.0;

texture ReliefTex { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; Format = RGBA8; };
sampler ReliefSampler { Texture = ReliefTex; };

float4 Edges(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float3 above = tex2D(ReShade::BackBuffer, texcoord - float2(0.0, BUFFER_RCP_HEIGHT)).rgb;
  float3 below = tex2D(ReShade::BackBuffer, texcoord + float2(0.0, BUFFER_RCP_HEIGHT)).rgb;
  return float4(saturate(0.5 + (below - above) * Strength), 1.0);
}

float4 Mix(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 colour = tex2D(ReShade::BackBuffer, texcoord);
  float3 relief = tex2D(ReliefSampler, texcoord).rgb;
  return float4(lerp(colour.rgb, relief, 0.5), colour.a);
}

technique Relief
{
  pass { VertexShader = PostProcessVS; PixelShader = Edges; RenderTarget = ReliefTex; }
  pass { VertexShader = PostProcessVS; PixelShader = Mix; }
}
