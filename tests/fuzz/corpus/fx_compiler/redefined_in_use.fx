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
#define SELF SELF + 1
#define MUTUAL_A MUTUAL_B
#define MUTUAL_B MUTUAL_A
#include "common.fxh"
#undef CAT
#define CAT(a, b) b##a
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  float SELF = 0, MUTUAL_A = 1;
  return tex2D(H::Back, uv) * (A + B + C + D) + CAT(0, 1) * 0.0;
}
#undef SCALE
#undef APPLY
technique Redefined { pass { VertexShader = VS; PixelShader = PS; } }
