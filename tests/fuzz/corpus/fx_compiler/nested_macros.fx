// Hand-written for the fuzz seeds: function-like macros inside one another, pasting that makes
// names of other macros, stringizing, variadic lists and a macro whose expansion opens a call.
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define CAT3(a, b, c) CAT(CAT(a, b), c)
#define STR_(x) #x
#define STR(x) STR_(x)
#define VEC(n) CAT(float, n)
#define MAT(r, c) CAT3(float, r, CAT(x, c))
#define FIRST(a, ...) a
#define REST(a, ...) __VA_ARGS__
#define APPLY(f, ...) f(__VA_ARGS__)
#define CALL_OPEN max(
#define TWICE(x) ((x) + (x))
#define SQUARE(x) ((x) * (x))
#define COMPOSE(f, g, x) f(g(x))
#define NAME_OF(kind, n) CAT3(kind, _, n)
#define DECLARE(kind, n, value) static const VEC(n) NAME_OF(kind, n) = value
#define EMPTY()
#define DEFER(m) m EMPTY()
#define LEVELS 4
DECLARE(gain, 3, VEC(3)(1, 2, 3));
DECLARE(bias, 2, float2(APPLY(FIRST, 0.5, 9), APPLY(REST, 9, 0.25)));
MAT(3, 3) Rotation = MAT(3, 3)(1, 0, 0, 0, 1, 0, 0, 0, 1);
texture2D BackTex : COLOR;
sampler2D Back { Texture = BackTex; };
float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  VEC(4) c = tex2D(Back, uv);
  [unroll] for (int i = 0; i < LEVELS; ++i)
    c.rgb = CALL_OPEN c.rgb, COMPOSE(TWICE, SQUARE, float(i) * 0.01) * gain_3);
  c.rg += bias_2 * (LEVELS > 2 ? 1 : 0);
  return float4(mul(Rotation, c.rgb), c.a);
}
void VS(uint id : SV_VertexID, out float4 p : SV_Position, out float2 uv : TEXCOORD) {
  uv = float2(id == 2 ? 2 : 0, id == 1 ? 2 : 0);
  p = float4(uv * float2(2, -2) + float2(-1, 1), 0, 1);
}
technique Nested < ui_label = STR(CAT3(Ne, st, ed)); > { pass { VertexShader = VS; PixelShader = PS; } }
