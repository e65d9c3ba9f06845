// A multi-pass blur: half-size targets with mip levels, blending into a target, a pass writing
// two render targets, and a technique that is hidden and times out.
#include "Common.fxh"

#define BLUR_SAMPLES 5

UI_SLIDER(Radius, "Radius", 0.5, 4.0, 1.0)

texture2D HalfTex { Width = BUFFER_WIDTH / 2; Height = BUFFER_HEIGHT / 2; Format = RGBA16F; MipLevels = 3; };
texture2D AccumTex { Width = BUFFER_WIDTH >> 1; Height = BUFFER_HEIGHT >> 1; Format = RGB10A2; };
texture2D LumaTex { Width = 1; Height = 1; Format = R32F; };
sampler2D Half { Texture = HalfTex; AddressU = MIRROR; AddressV = BORDER; MipLODBias = 0.5; MinLOD = 0; MaxLOD = 2.0f; };
sampler2D Accum { Texture = AccumTex; };
sampler2D Luma { Texture = LumaTex; MinFilter = POINT; };

static const float Weights[BLUR_SAMPLES] = { 0.2270270270, 0.1945945946, 0.1216216216, 0.0540540541, 0.0162162162 };

float4 DownPS(float4 position : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float4 sum = 0;
	[unroll] for (int x = -1; x <= 1; ++x)
		[unroll] for (int y = -1; y <= 1; ++y)
			sum += tex2Doffset(Common::BackBuffer, uv, int2(x, y));
	return sum / 9.0;
}

void BlurPS(float4 position : SV_Position, float2 uv : TEXCOORD, out float4 color : SV_Target0, out float luma : SV_Target1)
{
	color = tex2D(Half, uv) * Weights[0];
	[loop]
	for (int i = 1; i < BLUR_SAMPLES; i++)
	{
		float2 offset = float2(i * Radius * Common::PixelSize.x, 0.0);
		color += (tex2Dlod(Half, float4(uv + offset, 0, 1)) + tex2Dlod(Half, float4(uv - offset, 0, 1))) * Weights[i];
	}
	luma = dot(color.rgb, float3(0.299, 0.587, 0.114));
}

float4 CombinePS(float4 position : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float2 size = tex2Dsize(Accum, 0);
	float exposure = tex2Dfetch(Luma, int2(0, 0)).r;
	float4 gathered = tex2DgatherR(Half, uv);
	return float4(tex2D(Accum, uv + 0.5 / size).rgb * exposure + gathered.x * 0.0, 1.0);
}

technique Blur < hidden = false; timeout = 0; ui_tooltip = "Test blur"; >
{
	pass Down
	{
		VertexShader = PostProcessVS;
		PixelShader = DownPS;
		RenderTarget = HalfTex;
		GenerateMipMaps = true;
	}
	pass Blur
	{
		VertexShader = PostProcessVS;
		PixelShader = BlurPS;
		RenderTarget0 = AccumTex;
		RenderTarget1 = LumaTex;
		ClearRenderTargets = true;
		BlendEnable0 = true;
		BlendOp = ADD;
		SrcBlend = SRCALPHA;
		DestBlend = INVSRCALPHA;
		BlendOpAlpha = MAX;
		SrcBlendAlpha = ONE;
		DestBlendAlpha = ZERO;
		RenderTargetWriteMask = 0xF;
	}
	pass Combine
	{
		VertexShader = PostProcessVS;
		PixelShader = CombinePS;
		SRGBWriteEnable = false;
		StencilEnable = false;
		StencilFunc = ALWAYS;
		StencilPassOp = KEEP;
		PrimitiveTopology = TRIANGLELIST;
		VertexCount = 3;
	}
}
