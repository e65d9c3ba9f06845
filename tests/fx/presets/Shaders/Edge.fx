// A neighbourhood effect: each pixel moves away from the mean of its four neighbours by Strength,
// so it depends on the frame's size and on the order it runs in after Grade.
#include "ReShade.fxh"
uniform float Strength < ui_type = "slider"; ui_min = 0.0; ui_max = 4.0; > = 1.0;
float4 Edge(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  float3 c = tex2D(ReShade::BackBuffer, uv).rgb;
  float3 n = tex2D(ReShade::BackBuffer, uv + float2(BUFFER_RCP_WIDTH, 0)).rgb +
             tex2D(ReShade::BackBuffer, uv - float2(BUFFER_RCP_WIDTH, 0)).rgb +
             tex2D(ReShade::BackBuffer, uv + float2(0, BUFFER_RCP_HEIGHT)).rgb +
             tex2D(ReShade::BackBuffer, uv - float2(0, BUFFER_RCP_HEIGHT)).rgb;
  return float4(saturate(c + Strength * (c - 0.25 * n)), 1.0);
}
technique Edge { pass { VertexShader = PostProcessVS; PixelShader = Edge; } }
