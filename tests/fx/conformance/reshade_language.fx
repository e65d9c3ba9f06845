// Language that ReShade accepts and current public effects use: TRUE and FALSE as state values
// (any case), a backslash before a character that is no escape (kept, as in combo lists), a
// token paste that gives several valid tokens (kept as those tokens, with a warning), and a
// function with the name of a variable beside it.
// size: 64x2
#include "include/check.fxh"

uniform int Mode < ui_type = "combo"; ui_items = "Color\0\HSV: Hue\0\Luma\0"; > = 0;

#define GET_TINT(id) Tint##id##.rgb
static const float4 Tint1 = float4(0.25, 0.5, 0.75, 1.0);
static const float4 Tint2 = float4(1.0, 0.0, 0.5, 1.0);

// A call finds the function, a value the matrix: (1, 2, 3) scaled by 2, 3 and 4.
static const float3x3 Scale = float3x3(2, 0, 0, 0, 3, 0, 0, 0, 4);
float3 Scale(float3 c) { return mul(Scale, c); }

texture2D LinearTex { Width = 2; Height = 2; Format = RGBA8; };
sampler2D LinearSampler { Texture = LinearTex; SRGBTexture = FALSE; MagFilter = POINT; MinFilter = POINT; };
sampler2D SrgbSampler { Texture = LinearTex; SRGBTexture = TRUE; MagFilter = POINT; MinFilter = POINT; };

// 0.5 written to an RGBA8 target with no sRGB encoding reads back as 128 / 255; through an sRGB
// view that code decodes to ((128 / 255 + 0.055) / 1.055)^2.4 = 0.21586.
float4 Fill(float4 position : SV_Position) : SV_Target { return float4(0.5, 0.5, 0.5, 1.0); }

bool Check(int i)
{
  switch (i)
  {
    case 0: return Near(GET_TINT(1) + Zero, float3(0.25, 0.5, 0.75));
    case 1: return Near(GET_TINT(2) + Zero, float3(1.0, 0.0, 0.5));
    case 2: return Near(tex2D(LinearSampler, float2(0.25, 0.25)).r + Zero, 128.0 / 255.0);
    case 3: return Close(tex2D(SrgbSampler, float2(0.75, 0.75)).g + Zero, 0.21586);
    case 4: return Mode + IZero == 0;
    case 5: return Near(Scale(float3(1, 2, 3) + Zero), float3(2, 6, 12)) && Near(Scale[1][1] + Zero, 3.0);
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique reshade_language
{
  pass { VertexShader = PostProcessVS; PixelShader = Fill; RenderTarget = LinearTex; SRGBWriteEnable = FALSE; BlendEnable = false; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; ClearRenderTargets = TRUE; BlendEnable = FALSE; }
}
