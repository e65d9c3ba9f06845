// An odd frame size: textures of half the frame round down, every pixel still gets its own value.
// size: 28x5
#include "include/check.fxh"
#include "include/input_picture.fxh"
texture Half { Width = BUFFER_WIDTH / 3; Height = BUFFER_HEIGHT / 2; Format = R32F; };
sampler SHalf { Texture = Half; };
float4 Fill(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 1.0; }
float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  int2 p = int2(position.xy);
  bool ok = BUFFER_WIDTH == 28 && BUFFER_HEIGHT == 5 && all(tex2Dsize(SHalf) == int2(9, 2));
  ok = ok && SameCode(tex2Dfetch(ReShade::BackBuffer, p).rgb, InputPixel(p)) && tex2Dfetch(SHalf, int2(8, 1)).x == 1.0;
  return Verdict(ok);
}
technique size_odd
{
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = Half; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
