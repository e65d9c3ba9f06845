// A parameter reaching an effect on Vulkan through the FX plugin's "pfx.vulkan_effects/1" factory:
// the picture's colour times Gain, its alpha kept (run_vulkan_checks.py sets Gain and judges).
#include "ReShade.fxh"

uniform float Gain < ui_type = "slider"; ui_min = 0.0; ui_max = 2.0; > = 1.0;

float4 Scale(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 c = tex2D(ReShade::BackBuffer, texcoord);
  return float4(c.rgb * Gain, c.a);
}

technique gain { pass { VertexShader = PostProcessVS; PixelShader = Scale; } }
