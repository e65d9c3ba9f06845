// What the layer's tests check an effect the Vulkan runtime cannot run with: its first pass draws
// into a 3D texture (the GL runtime draws into the first layer), its second mixes that with the
// frame, half and half.
#include "ReShade.fxh"

texture3D VolumeTex { Width = 4; Height = 4; Depth = 4; Format = RGBA8; };
sampler3D sVolume { Texture = VolumeTex; };

float4 Fill(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return float4(1.0, 0.5, 0.0, 1.0);
}

float4 Show(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float4 colour = tex2D(ReShade::BackBuffer, texcoord);
  return float4(lerp(colour.rgb, tex3D(sVolume, float3(texcoord, 0.1)).rgb, 0.5), colour.a);
}

technique Volume
{
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = VolumeTex; }
  pass { VertexShader = PostProcessVS; PixelShader = Show; }
}
