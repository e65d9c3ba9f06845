// A small shared header in the style effect collections use: the frame's colour and depth, a
// full-screen vertex shader, depth linearisation, and macros that declare UI parameters.
#pragma once

#ifndef COMMON_DEPTH_REVERSED
	#define COMMON_DEPTH_REVERSED 0
#endif
#ifndef COMMON_DEPTH_FAR
	#define COMMON_DEPTH_FAR 1000.0
#endif

#define COMMON_STRINGIFY(x) #x
// Two levels, so a macro argument is expanded before it is stringized.
#define COMMON_STRINGIFY_VALUE(x) COMMON_STRINGIFY(x)
#define COMMON_CONCAT(a, b) a##b
// A slider in one line: UI_SLIDER(Strength, "Strength", 0.0, 1.0, 0.5)
#define UI_SLIDER(name, label, low, high, value) \
	uniform float name < \
		ui_type = "slider"; \
		ui_label = label; \
		ui_tooltip = "Parameter " COMMON_STRINGIFY(name); \
		ui_min = low; ui_max = high; \
	> = value;

namespace Common
{
	static const float2 PixelSize = float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT);
	static const float AspectRatio = BUFFER_WIDTH * BUFFER_RCP_HEIGHT;

	texture BackBufferTex : COLOR;
	texture DepthBufferTex : DEPTH;

	sampler BackBuffer { Texture = BackBufferTex; SRGBTexture = false; };
	sampler DepthBuffer { Texture = DepthBufferTex; MagFilter = POINT; MinFilter = POINT; MipFilter = POINT; };

	float GetLinearizedDepth(float2 texcoord)
	{
		float depth = tex2Dlod(DepthBuffer, float4(texcoord, 0, 0)).x;
#if COMMON_DEPTH_REVERSED
		depth = 1 - depth;
#endif
		const float N = 1.0;
		return depth / (COMMON_DEPTH_FAR - depth * (COMMON_DEPTH_FAR - N));
	}
}

void PostProcessVS(in uint id : SV_VertexID, out float4 position : SV_Position, out float2 texcoord : TEXCOORD)
{
	texcoord.x = (id == 2) ? 2.0 : 0.0;
	texcoord.y = (id == 1) ? 2.0 : 0.0;
	position = float4(texcoord * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
}
