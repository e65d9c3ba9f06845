// The frame's alpha passes through an FX effect untouched: FX shaders use the back buffer's alpha
// as scratch (FXAA keeps luma there), which a display never shows; here a pass writes 0 to it.
// input: alpha
// expect: input
// size: 40x9
#include "ReShade.fxh"
float4 Scribble(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return float4(tex2D(ReShade::BackBuffer, texcoord).rgb, 0.0);
}
technique alpha { pass { VertexShader = PostProcessVS; PixelShader = Scribble; } }
