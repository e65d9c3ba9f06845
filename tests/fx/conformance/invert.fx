// A colour effect on an 8-bit frame gives what ReShade gives on that frame: 255 - x, exactly.
// expect: invert
// size: 64x16
#include "ReShade.fxh"
float4 Invert(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return float4(1.0 - tex2D(ReShade::BackBuffer, texcoord).rgb, 1.0);
}
technique invert { pass { VertexShader = PostProcessVS; PixelShader = Invert; } }
