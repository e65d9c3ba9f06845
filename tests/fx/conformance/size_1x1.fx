// A one-pixel frame: the back buffer, BUFFER_WIDTH and a pass that reads a neighbour all work.
// expect: input
// size: 1x1
#include "ReShade.fxh"
float4 Copy(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return BUFFER_WIDTH == 1 && BUFFER_HEIGHT == 1 ? tex2D(ReShade::BackBuffer, texcoord + BUFFER_PIXEL_SIZE) : 0.0;
}
technique size_1x1 { pass { VertexShader = PostProcessVS; PixelShader = Copy; } }
