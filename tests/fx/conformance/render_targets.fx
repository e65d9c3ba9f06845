// Several render targets of one size in one pass (SV_Target0..3, from out parameters and a
// struct), a texture sized in a fraction of the frame, and ClearRenderTargets.
// size: 32x4
#include "include/check.fxh"

texture A { Width = 3; Height = 2; Format = R32F; };
texture B { Width = 3; Height = 2; Format = RG32F; };
texture C { Width = 3; Height = 2; Format = RGBA32F; };
texture D { Width = 3; Height = 2; Format = RGBA8; };
texture Fraction { Width = BUFFER_WIDTH / 2; Height = BUFFER_HEIGHT / 2; Format = R32F; };
sampler SFraction { Texture = Fraction; };
texture Cleared { Format = R32F; };
sampler SA { Texture = A; };
sampler SB { Texture = B; };
sampler SC { Texture = C; };
sampler SD { Texture = D; };
sampler SCleared { Texture = Cleared; };

struct Outputs
{
  float4 c : SV_Target2;
  float4 d : SV_Target3;
};

void WriteAll(float4 position : SV_Position, float2 texcoord : TEXCOORD, out float4 a : SV_Target0, out float4 b : SV_Target1, out Outputs rest)
{
  a = 1.0;
  b = float4(2.0, 3.0, 0.0, 0.0);
  rest.c = float4(4.0, 5.0, 6.0, 7.0);
  rest.d = float4(0.2, 0.4, 0.6, 0.8);
}
float4 Fill(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 9.0; }
float4 Skip(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { discard; return 9.0; }

bool Check(int i)
{
  switch (i)
  {
    case 0: return tex2Dfetch(SA, int2(2, 1) + IZero).x == 1.0 && tex2Dfetch(SFraction, int2(15, 1) + IZero).x == 9.0 && all(tex2Dsize(SFraction) == int2(16, 2));
    case 1: return all(tex2Dfetch(SB, int2(2, 1) + IZero).xy == float2(2.0, 3.0));
    case 2: return all(tex2Dfetch(SC, int2(1, 0) + IZero) == float4(4.0, 5.0, 6.0, 7.0));
    case 3: return Near(tex2Dfetch(SD, int2(2, 0) + IZero), float4(51, 102, 153, 204) / 255.0);
    case 4: return tex2Dfetch(SCleared, int2(0, 0) + IZero).x == 0.0;  // cleared, then nothing drawn
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique render_targets
{
  pass { VertexShader = PostProcessVS; PixelShader = WriteAll; RenderTarget0 = A; RenderTarget1 = B; RenderTarget2 = C; RenderTarget3 = D; }
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = Fraction; }
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = Cleared; }
  pass { VertexShader = PostProcessVS; PixelShader = Skip; RenderTarget = Cleared; ClearRenderTargets = true; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
