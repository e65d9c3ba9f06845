// The 8-bit round trip: a technique that hands the back buffer on untouched gives the input
// picture back byte for byte (decode, encode to the back buffer, decode, encode).
// expect: input
// size: 61x37
#include "ReShade.fxh"
float4 Copy(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target { return tex2D(ReShade::BackBuffer, texcoord); }
technique identity { pass { VertexShader = PostProcessVS; PixelShader = Copy; } }
