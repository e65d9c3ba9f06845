// Stencil states: one 8-bit stencil buffer of the frame's size, cleared to 0 when the technique
// starts (every frame: two frames are rendered) and kept from pass to pass. Each pass below works on
// the four quarters q0..q3 of the frame's width; the stencil values after each are worked out by
// hand in the comments, and passes that test the stencil write 1 into a texture of their own
// (cleared first) where the test passes. A pass into a target of another size draws without
// stencil. (stencil_back_buffer.fx: a stencil pass into the back buffer.)
// size: 64x4
// frames: 2
#include "include/check.fxh"

texture TScratch { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TEqual { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TNotEqual { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TMasked { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TWide { Width = BUFFER_WIDTH + 1; Height = BUFFER_HEIGHT; };
texture TIs252 { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TIs12 { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TLess { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
texture TGreaterEqual { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; };
sampler SEqual { Texture = TEqual; MinFilter = POINT; MagFilter = POINT; };
sampler SNotEqual { Texture = TNotEqual; MinFilter = POINT; MagFilter = POINT; };
sampler SMasked { Texture = TMasked; MinFilter = POINT; MagFilter = POINT; };
sampler SWide { Texture = TWide; MinFilter = POINT; MagFilter = POINT; };
sampler SIs252 { Texture = TIs252; MinFilter = POINT; MagFilter = POINT; };
sampler SIs12 { Texture = TIs12; MinFilter = POINT; MagFilter = POINT; };
sampler SLess { Texture = TLess; MinFilter = POINT; MagFilter = POINT; };
sampler SGreaterEqual { Texture = TGreaterEqual; MinFilter = POINT; MagFilter = POINT; };

int Quarter(float4 position) { return int(position.x * 4.0 / BUFFER_WIDTH); }

float4 One(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return 1.0; }
float4 NotRight(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (Quarter(position) >= 2) discard;
  return 1.0;
}
float4 NotQ0(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (Quarter(position) == 0) discard;
  return 1.0;
}
float4 NotQ1(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (Quarter(position) == 1) discard;
  return 1.0;
}
float4 NotQ3(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  if (Quarter(position) == 3) discard;
  return 1.0;
}

// Whether the texture holds 1 in each quarter: bit q of `expected` for quarter q.
bool Quarters(sampler s, int expected)
{
  bool ok = true;
  for (int q = 0; q < 4; ++q)
  {
    bool one = tex2Dlod(s, float4((q + 0.5) / 4.0 + Zero, 0.5, 0.0, 0.0)).r > 0.5;
    ok = ok && one == (((expected >> q) & 1) != 0);
  }
  return ok;
}

bool Check(int i)
{
  if (i == 0) return Quarters(SEqual, 3);         // EQUAL 1 where 1: q0 and q1
  if (i == 1) return Quarters(SNotEqual, 2);      // NOTEQUAL 1 where 2: q1
  if (i == 2) return Quarters(SMasked, 13);       // EQUAL 0x10 under read mask 1, even values: q0, q2, q3
  if (i == 3) return Quarters(SWide, 15);         // one column wider: no stencil, every pixel written
  if (i == 4) return Quarters(SIs252, 5);         // q0 and q2 hold 252
  if (i == 5) return Quarters(SIs12, 2);          // q1 holds 12
  if (i == 6) return Quarters(SLess, 8);          // 253 < stencil: q3 (255)
  if (i == 7) return Quarters(SGreaterEqual, 7);  // 252 >= stencil: q0, q1, q2
  return true;
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique stencil
{
  // REPLACE with 1 where the shader does not discard: stencil q0..q3 = 1 1 0 0.
  pass { VertexShader = PostProcessVS; PixelShader = NotRight; RenderTarget = TScratch; StencilEnable = true; StencilPass = REPLACE; StencilRef = 1; }
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TEqual; ClearRenderTargets = true; StencilEnable = true; StencilFunc = EQUAL; StencilRef = 1; }
  // INCR (wraps) where not discarded, the test always passing: 1 2 1 1.
  pass { VertexShader = PostProcessVS; PixelShader = NotQ0; RenderTarget = TScratch; StencilEnable = true; StencilPassOp = INCR; }
  // NOTEQUAL 1 passes in q1 only (DECR there: 1); it fails elsewhere (INCRSAT there: 2): 2 1 2 2.
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TNotEqual; ClearRenderTargets = true; StencilEnable = true;
         StencilFunc = NOTEQUAL; StencilRef = 1; StencilPassOp = DECR; StencilFailOp = INCRSAT; }
  // (0x10 & 1) == (stencil & 1) passes where the value is even, which become ZERO: 0 1 0 0.
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TMasked; ClearRenderTargets = true; StencilEnable = true;
         StencilFunc = EQUAL; StencilRef = 0x10; StencilMask = 0x01; StencilPass = ZERO; }
  // DECR wraps 0 to 255 except in q1: 255 1 255 255.
  pass { VertexShader = PostProcessVS; PixelShader = NotQ1; RenderTarget = TScratch; StencilEnable = true; StencilPass = DECR; }
  // REPLACE with 0x3C through the write mask 0x0F, except in q3: (255 & 0xF0) | 0x0C = 252, (1 & 0xF0) | 0x0C = 12:
  // 252 12 252 255.
  pass { VertexShader = PostProcessVS; PixelShader = NotQ3; RenderTarget = TScratch; StencilEnable = true; StencilWriteMask = 0x0F;
         StencilPass = REPLACE; StencilRef = 0x3C; }
  // A target one column wider than the frame: drawn without stencil (NEVER would reject all, ZERO
  // would clear it).
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TWide; ClearRenderTargets = true; StencilEnable = true;
         StencilFunc = NEVER; StencilFailOp = ZERO; }
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TIs252; ClearRenderTargets = true; StencilEnable = true; StencilFunc = EQUAL; StencilRef = 252; }
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TIs12; ClearRenderTargets = true; StencilEnable = true; StencilFunc = EQUAL; StencilRef = 12; }
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TLess; ClearRenderTargets = true; StencilEnable = true; StencilFunc = LESS; StencilRef = 253; }
  pass { VertexShader = PostProcessVS; PixelShader = One; RenderTarget = TGreaterEqual; ClearRenderTargets = true; StencilEnable = true;
         StencilFunc = GEQUAL; StencilRef = 252; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
