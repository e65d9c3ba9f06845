// Hand-written for the fuzz seeds: macros #undef'd and #define'd again while they are in use, in
// an argument list, between uses, and by a header the file includes in the middle.
#define SCALE(x) ((x) * 2.0)
#define OFFSET 0.25
#define APPLY(f, x) f(x)
static const float A = APPLY(SCALE,
#undef SCALE
#define SCALE(x) ((x) * 3.0)
1.0) + OFFSET;
static const float B = SCALE(1.0);
#undef OFFSET
#define OFFSET -OFFSET_BASE
#define OFFSET_BASE 0.5
static const float C = OFFSET;
#undef OFFSET_BASE
#define OFFSET_BASE OFFSET
static const float D = 1.0;
static const float self_scale = 0.5, mutual_a = 0.25, mutual_b = 0.125;
#define self_scale (self_scale * 2.0)
#define mutual_a (mutual_b + 1.0)
#define mutual_b (mutual_a * 0.5)
#include "common.fxh"
#undef CAT
#define CAT(a, b) b##a
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  return tex2D(H::Back, uv) * (A + B + C + D) * self_scale * mutual_a + CAT(0, 1) * 0.0;
}
#undef SCALE
#undef APPLY
technique Redefined { pass { VertexShader = VS; PixelShader = PS; } }
