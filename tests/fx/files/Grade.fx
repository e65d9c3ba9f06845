// Colour grading the way public effects write it: UI parameters of every kind, a 3D LUT from a
// file, structs, overloads, loops with attributes and a switch on a combo box.
#include "Common.fxh"
#include "Common.fxh" // twice on purpose: #pragma once

#ifndef GRADE_LUT_SIZE
	#define GRADE_LUT_SIZE 16
#endif

UI_SLIDER(Strength, "Strength", 0.0, 1.0, 0.75)

uniform int Mode <
	ui_type = "combo";
	ui_label = "Mode";
	ui_items = "Neutral\0Warm\0"
	           "Cold\0";
	ui_category = "Look";
> = 1;

uniform float3 Tint < ui_type = "color"; ui_label = "Tint"; > = float3(1.0, 0.95, 0.9);
uniform bool UseLut < ui_label = "Use LUT"; ui_tooltip = "Applies " COMMON_STRINGIFY_VALUE(GRADE_LUT_SIZE) "^3 LUT"; > = true;
uniform float2 Range < ui_type = "drag"; ui_min = -1.0; ui_max = 1.0; ui_step = 0.01; > = float2(0.0, 1.0);
uniform float Timer < source = "timer"; >;
uniform int Frame < source = "framecount"; >;

texture3D LutTex < source = "grade_lut.png"; > { Width = GRADE_LUT_SIZE; Height = GRADE_LUT_SIZE; Depth = GRADE_LUT_SIZE; Format = RGBA8; };
sampler3D Lut { Texture = LutTex; AddressU = CLAMP; AddressV = CLAMP; AddressW = CLAMP; MinFilter = LINEAR; MagFilter = LINEAR; };

static const float3 LumaWeights = float3(0.2126, 0.7152, 0.0722);
static const float Curve[4] = { 0.0, 0.3, 0.7, 1.0 };
static const float3x3 WarmMatrix = float3x3(
	1.05, 0.0, 0.0,
	0.0, 1.0, 0.0,
	0.0, 0.0, 0.9);

struct Look
{
	float3 lift, gamma;
	float gain;
};

float Luma(float3 color) { return dot(color, LumaWeights); }
float Luma(float4 color) { return Luma(color.rgb) * color.a; }

Look MakeLook(int mode)
{
	Look look;
	look.lift = 0.0;
	look.gamma = 1.0;
	look.gain = 1.0;
	[forcecase] switch (mode)
	{
		case 1:
			look.gamma = float3(0.95, 1.0, 1.05);
			break;
		case 2:
		case 3:
			look.lift.b = 0.02;
			look.gain = 1.1;
			break;
		default:
			break;
	}
	return look;
}

float3 ApplyCurve(float3 color)
{
	float3 result = 0;
	[unroll]
	for (int i = 0; i < 3; i++)
	{
		float x = saturate(color[i]) * 3.0;
		int index = min((int)x, 2);
		result[i] = lerp(Curve[index], Curve[index + 1], frac(x));
	}
	return result;
}

float4 GradePS(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
	float4 color = tex2D(Common::BackBuffer, texcoord);
	const Look look = MakeLook(Mode);
	color.rgb = pow(max(color.rgb + look.lift, 0.0), 1.0 / look.gamma) * look.gain;
	if (Mode == 1)
		color.rgb = mul(WarmMatrix, color.rgb);
	else if (Mode == 2)
		color.rgb = color.bgr * 0.5 + color.rgb * 0.5;
	color.rgb = lerp(color.rgb, ApplyCurve(color.rgb), Strength) * Tint;
	if (UseLut)
	{
		float3 coord = (color.rgb * (GRADE_LUT_SIZE - 1) + 0.5) / GRADE_LUT_SIZE;
		color.rgb = tex3D(Lut, coord).rgb;
	}
	float luma = Luma(color);
	color.rgb = clamp(color.rgb, Range.x, Range.y) + (luma - luma.xxx) * 0.0;
	color.a = 1.0;
	return color;
}

technique Grade < ui_label = "Grade (test)"; ui_tooltip = "Lift, gamma, gain and a LUT"; enabled = true; >
{
	pass
	{
		VertexShader = PostProcessVS;
		PixelShader = GradePS;
	}
}
