// technique initializer_assignments pass 
#version 450
struct S_Window {
  int m_Masks[9];
  vec2 m_Centre;
};
struct S_Pair {
  float m_a;
  int m_b;
};
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
struct S_Window {
  int m_Masks[9];
  vec2 m_Centre;
};
struct S_Pair {
  float m_a;
  int m_b;
};
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
#line 15 2
bool F_Near(float l_a, float l_b)
#line 15 2
{
#line 15 2
  return (abs((l_a - l_b)) <= (9.99999975e-06 * max(1.0, abs(l_b))));
}
#line 16 2
bool F_Near(vec2 l_a, vec2 l_b)
#line 16 2
{
#line 16 2
  return (F_Near(l_a.x, l_b.x) && F_Near(l_a.y, l_b.y));
}
#line 12 1
bool F_Check(int l_i)
#line 13 1
{
#line 14 1
  S_Window l_windows[2];
#line 15 1
  (l_windows[0].m_Masks = int[9](1, 1, 1, 1, 1, 0, 1, 0, 0));
#line 16 1
  (l_windows[1].m_Masks = int[9](0, 0, 0, 0, 0, 0, 0, 0, (9 + G_IZero)));
#line 17 1
  (l_windows[1].m_Centre = vec2(0.0, 0.0));
#line 18 1
  float l_weights[3];
#line 19 1
  (l_weights = float[3]((0.5 + G_Zero), 0.25, float(1)));
#line 20 1
  vec2 l_corners[2];
#line 21 1
  (l_corners = vec2[2](vec2(1.0, 2.0), vec2((3.0 + G_Zero), 4.0)));
#line 22 1
  S_Pair l_pair;
#line 23 1
  (l_pair = S_Pair(0.75, 3));
#line 24 1
  switch (l_i) {
    case 0:
#line 26 1
      return ((((l_windows[0].m_Masks[4] == 1) && (l_windows[0].m_Masks[5] == 0)) && (l_windows[0].m_Masks[6] == 1)) && (l_windows[0].m_Masks[8] == 0));
    case 1:
#line 27 1
      return ((l_windows[1].m_Masks[8] == 9) && (l_windows[1].m_Masks[0] == 0));
    case 2:
#line 28 1
      return ((F_Near(l_weights[0], 0.5) && F_Near(l_weights[1], 0.25)) && F_Near(l_weights[2], 1.0));
    case 3:
#line 29 1
      return (F_Near(l_corners[0], vec2(1.0, 2.0)) && F_Near(l_corners[1], vec2(3.0, 4.0)));
    case 4:
#line 30 1
      return (F_Near(l_pair.m_a, 0.75) && (l_pair.m_b == 3));
    default:
#line 31 1
      return true;
  }
}
#line 35 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 36 1
{
#line 37 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 35 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   initializer_assignments.fx
1 of 1 files parse
