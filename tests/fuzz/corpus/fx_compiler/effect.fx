#include "common.fxh"
uniform float Amount < ui_type = "slider"; ui_min = 0.0; ui_max = 1.0; > = 0.5;
static const float W[3] = { 0.25, 0.5, 0.25 };
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float4 c = 0;
	[unroll] for (int i = -1; i <= 1; i++) c += tex2D(H::Back, uv + float2(i, 0) * BUFFER_RCP_WIDTH) * W[i + 1];
	return lerp(tex2D(H::Back, uv), c, Amount);
}
technique Blur < ui_label = STR(Blur); > { pass { VertexShader = VS; PixelShader = PS; } }
