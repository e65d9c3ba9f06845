// A type error: a float3 cannot become a sampler.
#include "ReShade.fxh"
float4 Bad(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  return tex2D(float3(1, 2, 3), uv);
}
technique Broken { pass { VertexShader = PostProcessVS; PixelShader = Bad; } }
