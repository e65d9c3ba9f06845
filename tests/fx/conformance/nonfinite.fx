// A frame holding NaN, +Inf, -Inf, values above 65504 and negative colour: FX shaders see it
// clamped to the display range [0, 1] (NaN as 0), and the output is finite.
// input: nan
// expect: finite
// size: 16x3
#include "ReShade.fxh"
float4 Brighten(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 c = tex2D(ReShade::BackBuffer, texcoord);
  return float4(c.rgb * 1.5, 1.0);
}
technique nonfinite { pass { VertexShader = PostProcessVS; PixelShader = Brighten; } }
