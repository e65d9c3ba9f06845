// A file that compiles: two techniques, one with a label, and an image texture found in the
// collection's Textures folder.
#include "ReShade.fxh"
uniform float Amount < ui_type = "slider"; ui_min = 0.0; ui_max = 1.0; ui_label = "Amount"; > = 0.5;
texture Stamp < source = "stamp.png"; > { Width = 2; Height = 2; };
sampler SStamp { Texture = Stamp; };
float4 Tint(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  return lerp(tex2D(ReShade::BackBuffer, uv), tex2D(SStamp, uv), Amount);
}
technique GoodTint < ui_label = "Good tint"; > { pass { VertexShader = PostProcessVS; PixelShader = Tint; } }
technique GoodSecond { pass { VertexShader = PostProcessVS; PixelShader = Tint; } }
