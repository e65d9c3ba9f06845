// technique namespaced_constants pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) out vec4 pfx_v_TEXCOORD0;
#line 63 3
void F_PostProcessVS(uint l_id, out vec4 l_position, out vec2 l_texcoord)
#line 64 3
{
#line 65 3
  (l_texcoord = vec2(((l_id == uint(2)) ? 2.0 : 0.0), ((l_id == uint(1)) ? 2.0 : 0.0)));
#line 66 3
  (l_position = vec4(((l_texcoord * vec2(2.0, (-2.0))) + vec2((-1.0), 1.0)), 0.0, 1.0));
}
#line 63 3
void main() {
  pfx_v_TEXCOORD0 = vec4(0);
  uint p0;
  vec4 p1;
  vec2 p2;
  p0 = uint(gl_VertexID);
  F_PostProcessVS(p0, p1, p2);
  gl_Position = p1;
  pfx_v_TEXCOORD0 = vec4(p2, 0, 1);
}
#version 450
float G_Filmic_ns_A;
float G_Filmic_ns_B;
float G_Filmic_ns_W;
float G_Filmic_ns_WhiteScale;
float G_Filmic_ns_Folded;
float G_Filmic_ns_Inner_ns_Pi;
float G_Filmic_ns_Inner_ns_TwoPi;
float G_Filmic_ns_Table[3];
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
int pfx_ftoi(float x) { return x >= 2147483648.0 ? 2147483647 : x > -2147483648.0 ? int(x) : x < 0.0 ? (-2147483647 - 1) : 0; }
ivec2 pfx_ftoi(vec2 x) { return mix(mix(mix(ivec2(0), ivec2(-2147483647 - 1), lessThan(x, vec2(0.0))), ivec2(x), greaterThan(x, vec2(-2147483648.0))), ivec2(2147483647), greaterThanEqual(x, vec2(2147483648.0))); }
ivec3 pfx_ftoi(vec3 x) { return mix(mix(mix(ivec3(0), ivec3(-2147483647 - 1), lessThan(x, vec3(0.0))), ivec3(x), greaterThan(x, vec3(-2147483648.0))), ivec3(2147483647), greaterThanEqual(x, vec3(2147483648.0))); }
ivec4 pfx_ftoi(vec4 x) { return mix(mix(mix(ivec4(0), ivec4(-2147483647 - 1), lessThan(x, vec4(0.0))), ivec4(x), greaterThan(x, vec4(-2147483648.0))), ivec4(2147483647), greaterThanEqual(x, vec4(2147483648.0))); }
#line 9 2
int F_CheckIndex(vec4 l_position)
#line 9 2
{
#line 9 2
  return (pfx_ftoi(l_position.x) / 4);
}
#line 11 2
vec4 F_Verdict(bool l_ok)
#line 11 2
{
#line 11 2
  return (l_ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0));
}
#line 14 2
bool F_Close(float l_a, float l_b)
#line 14 2
{
#line 14 2
  return (abs((l_a - l_b)) <= (0.00100000005 * max(1.0, abs(l_b))));
}
#line 15 2
bool F_Near(float l_a, float l_b)
#line 15 2
{
#line 15 2
  return (abs((l_a - l_b)) <= (9.99999975e-06 * max(1.0, abs(l_b))));
}
#line 21 1
vec3 F_Filmic_ns_Curve(vec3 l_x)
#line 21 1
{
#line 21 1
  return ((l_x * ((vec3(G_Filmic_ns_A) * l_x) + vec3(G_Filmic_ns_B))) * vec3(G_Filmic_ns_WhiteScale));
}
#line 24 1
bool F_Check(int l_i)
#line 25 1
{
#line 26 1
  switch (l_i) {
    case 0:
#line 28 1
      return ((F_Near(G_Filmic_ns_A, 0.150000006) && F_Near(G_Filmic_ns_B, 0.5)) && F_Near((G_Filmic_ns_Folded + G_Zero), 1.0));
    case 1:
#line 29 1
      return F_Near(G_Filmic_ns_WhiteScale, 0.227272734);
    case 2:
#line 30 1
      return (F_Close((G_Filmic_ns_Inner_ns_Pi + G_Zero), 3.14159274) && F_Close((G_Filmic_ns_Inner_ns_TwoPi + G_Zero), 6.28318548));
    case 3:
#line 31 1
      return F_Near(F_Filmic_ns_Curve((vec3(0.5, 0.5, 0.5) + vec3(G_Zero))).x, 0.0653409064);
    case 4:
#line 32 1
      return ((F_Near(G_Filmic_ns_Table[0], 0.150000006) && F_Near(G_Filmic_ns_Table[(1 + G_IZero)], 0.5)) && F_Close(G_Filmic_ns_Table[2], 3.14159274));
    default:
#line 33 1
      return true;
  }
}
#line 37 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 38 1
{
#line 39 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 37 1
void main() {
  G_Filmic_ns_A = (0.150000006 + G_Zero);
  G_Filmic_ns_B = (G_Filmic_ns_A + 0.349999994);
  G_Filmic_ns_W = 4.0;
  G_Filmic_ns_WhiteScale = (1.0 / (G_Filmic_ns_W * ((G_Filmic_ns_A * G_Filmic_ns_W) + G_Filmic_ns_B)));
  G_Filmic_ns_Folded = (0.25 * 4.0);
  G_Filmic_ns_Inner_ns_Pi = acos((-1.0));
  G_Filmic_ns_Inner_ns_TwoPi = (2.0 * G_Filmic_ns_Inner_ns_Pi);
  G_Filmic_ns_Table = float[3](G_Filmic_ns_A, G_Filmic_ns_B, G_Filmic_ns_Inner_ns_Pi);
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   namespaced_constants.fx
1 of 1 files parse
