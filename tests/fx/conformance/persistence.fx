// Textures keep their contents from one frame to the next, and the frame's sources reach
// uniforms: after frames 0, 1 and 2 a counter incremented once a frame holds 3, and framecount
// is 2 in the last frame.
// frames: 3
// size: 16x2
#include "include/check.fxh"

texture Counter { Format = R32F; };
texture Scratch { Format = R32F; };
sampler SCounter { Texture = Counter; };
sampler SScratch { Texture = Scratch; };
uniform int FrameCount < source = "framecount"; >;
uniform float FrameTime < source = "frametime"; >;
uniform float Timer < source = "timer"; >;

float4 Increment(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return tex2Dfetch(SCounter, int2(0, 0)).x + 1.0; }
float4 Store(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return tex2Dfetch(SScratch, int2(0, 0)).x; }

bool Check(int i)
{
  switch (i)
  {
    case 0: return tex2Dfetch(SCounter, int2(0, 0) + IZero).x == 3.0;
    case 1: return FrameCount == 2;
    case 2: return FrameTime >= 0.0 && Timer >= 0.0;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique persistence
{
  pass { VertexShader = PostProcessVS; PixelShader = Increment; RenderTarget = Scratch; }
  pass { VertexShader = PostProcessVS; PixelShader = Store; RenderTarget = Counter; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
