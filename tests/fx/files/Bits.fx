// Integer and bit operations, reinterpretation, half conversion, matrices of every shape,
// scalar and matrix swizzles, while/do loops, sincos and renderer-dependent code.
#include "Common.fxh"

#if __RENDERER__ >= 0x10000 && __RENDERER__ < 0x20000
	#define BITS_OPENGL 1
#else
	#define BITS_OPENGL 0
#endif

#if !defined(__RESHADE__) || __RESHADE__ < 40000
	#error "this effect needs ReShade 4 or newer"
#endif

uniform uint Seed < ui_type = "input"; > = 0x9E3779B9u;
uniform float Angle < ui_type = "slider"; ui_min = -3.14159; ui_max = 3.14159; ui_units = " rad"; > = 0.5;

uint Hash(uint x)
{
	x ^= x >> 16;
	x *= 0x7feb352du;
	x ^= x >> 15;
	x *= 0x846ca68bu;
	return x ^ (x >> 16);
}

float Random(float2 uv)
{
	uint2 cell = uint2(uv * float2(BUFFER_WIDTH, BUFFER_HEIGHT));
	uint h = Hash(cell.x ^ Hash(cell.y + Seed));
	return asfloat((h >> 9) | 0x3f800000u) - 1.0;
}

float2 Rotate(float2 v, float angle)
{
	float s, c;
	sincos(angle, s, c);
	float2x2 rotation = float2x2(c, -s, s, c);
	return mul(rotation, v);
}

float3 Project(float3 v)
{
	float3x2 basis = float3x2(1, 0, 0, 1, 0.5, 0.5);
	float2 flat = mul(v, basis);
	float3 back = mul(basis, flat);
	return back + basis._m00 * v.xxx + float3(basis._11_21_31) * 0.0;
}

int CountSteps(int n)
{
	int steps = 0;
	while (n > 1)
	{
		n = (n % 2 == 0) ? n / 2 : 3 * n + 1;
		if (++steps > 100)
			break;
	}
	do { steps--; } while (steps > 50);
	return steps;
}

float4 BitsPS(float4 position : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float4 color = tex2D(Common::BackBuffer, Rotate(uv - 0.5, Angle) + 0.5);
	uint packed = f32tof16(color.r) | (f32tof16(color.g) << 16);
	color.rg = float2(f16tof32(packed & 0xFFFF), f16tof32(packed >> 16));
	int bits = countbits(packed) + firstbithigh(packed) - (int)reversebits(packed & 1u);
	color.b += (bits % 3) * 0.0 + Random(uv) / 255.0;
	color.rgb = Project(color.rgb);
	bool3 isBad = isnan(color.rgb) || isinf(color.rgb);
	color.rgb = any(isBad) ? 0.0.xxx : color.rgb;
	color.a = BITS_OPENGL ? 1.0 : 0.5;
	color.a = (float)CountSteps(27) * 0.0 + color.a;
	return color;
}

technique Bits { pass { VertexShader = PostProcessVS; PixelShader = BitsPS; } }
