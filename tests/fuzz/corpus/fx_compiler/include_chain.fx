// Hand-written for the fuzz seeds: a chain of headers carried in the input (the fuzz target's
// "//@file" lines), with include guards, #pragma once, a macro defined in one header and used in
// the next, and a header included twice.
#include "first.fxh"
#include "second.fxh"
#include "first.fxh"
#include "inc/third.fxh"
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  return THIRD_COLOUR(tex2D(Back, uv));
}
technique Chain < ui_label = CHAIN_NAME; > { pass { VertexShader = VS; PixelShader = PS; } }
//@file first.fxh
#ifndef FIRST_FXH
#define FIRST_FXH
#define CHAIN_NAME "chain of " __FILE__
#define GAIN 1.5
texture2D BackTex : COLOR;
sampler2D Back { Texture = BackTex; };
#endif
//@file second.fxh
#pragma once
#include "first.fxh"
#define SECOND(c) ((c) * GAIN)
void VS(uint id : SV_VertexID, out float4 p : SV_Position, out float2 uv : TEXCOORD) {
  uv = float2(id == 2 ? 2 : 0, id == 1 ? 2 : 0);
  p = float4(uv * float2(2, -2) + float2(-1, 1), 0, 1);
}
//@file third.fxh
#pragma once
#include "second.fxh"
#undef GAIN
#define GAIN 0.5
#define THIRD_COLOUR(c) saturate(SECOND(c) + __LINE__ * 0.0)
