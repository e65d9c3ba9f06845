// Passes that render to the back buffer: the next pass reads what the last one wrote, and pixels a
// pass discards keep what they held. The left half (x < 32) is rewritten, the right half kept.
// size: 64x2
#include "include/check.fxh"
#include "include/input_picture.fxh"

float4 Rewrite(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (position.x >= 32.0) discard;
  return float4(0.5, tex2D(ReShade::BackBuffer, texcoord).gb, 1.0);
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  int2 p = int2(position.xy);
  float3 seen = tex2Dfetch(ReShade::BackBuffer, p).rgb;
  float3 input = InputPixel(p);
  bool ok = p.x < 32 ? SameCode(seen, float3(128.0 / 255.0, input.gb)) : SameCode(seen, input);
  return Verdict(ok);
}

technique back_buffer
{
  pass { VertexShader = PostProcessVS; PixelShader = Rewrite; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
