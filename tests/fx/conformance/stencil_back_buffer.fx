// A stencil pass into the back buffer draws only where its test passes and keeps the other pixels:
// the left half of the stencil holds 1, a pass writes red into the right half of the back buffer
// (green into the left), and a pass whose test passes where the stencil holds 0 writes green there
// and red elsewhere. Every pixel is green when the test limits that pass to the right half and
// the left half keeps the earlier pass's green.
// size: 64x4
#include "include/check.fxh"

texture TScratch { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };

bool Right(float4 position) { return position.x >= BUFFER_WIDTH / 2; }

float4 MarkLeft(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (Right(position)) discard;
  return 1.0;
}
float4 GreenLeft(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return Verdict(!Right(position)); }
float4 GreenRight(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return Verdict(Right(position)); }

technique stencil_back_buffer
{
  pass { VertexShader = PostProcessVS; PixelShader = MarkLeft; RenderTarget = TScratch; StencilEnable = true; StencilPass = REPLACE; StencilRef = 1; }
  pass { VertexShader = PostProcessVS; PixelShader = GreenLeft; }
  pass { VertexShader = PostProcessVS; PixelShader = GreenRight; StencilEnable = true; StencilFunc = EQUAL; StencilRef = 0; }
}
