// technique uniforms pass 
#version 450
layout(set = 0, binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  float G_Strength;
  vec3 G_Tint;
  vec4 G_Edge;
  int G_Mode;
  bool G_Enabled;
  ivec2 G_Cells;
  uint G_Big;
  float G_Weights[3];
  mat2 G_Rows;
  float G_Unset;
  mat3 G_Frames[2];
  float G_Last;
  ivec2[2] G_IRows;
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
  p0 = uint(gl_VertexIndex);
  F_PostProcessVS(p0, p1, p2);
  gl_Position = p1;
  gl_Position.y = -gl_Position.y;
  pfx_v_TEXCOORD0 = vec4(p2, 0, 1);
}
#version 450
layout(set = 0, binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  float G_Strength;
  vec3 G_Tint;
  vec4 G_Edge;
  int G_Mode;
  bool G_Enabled;
  ivec2 G_Cells;
  uint G_Big;
  float G_Weights[3];
  mat2 G_Rows;
  float G_Unset;
  mat3 G_Frames[2];
  float G_Last;
  ivec2[2] G_IRows;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
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
#line 17 2
bool F_Near(vec3 l_a, vec3 l_b)
#line 17 2
{
#line 17 2
  return (F_Near(l_a.xy, l_b.xy) && F_Near(l_a.z, l_b.z));
}
#line 21 1
bool F_Check(int l_i)
#line 22 1
{
#line 23 1
  switch (l_i) {
    case 0:
#line 25 1
      return (G_Strength == 0.75);
    case 1:
#line 26 1
      return F_Near(G_Tint, vec3(0.100000001, 0.200000003, 0.300000012));
    case 2:
#line 27 1
      return all(equal(G_Edge, vec4(0.5, 0.25, 0.125, 0.0625)));
    case 3:
#line 28 1
      return ((G_Mode == 2) && G_Enabled);
    case 4:
#line 29 1
      return (all(equal(G_Cells, ivec2((-3), 4))) && (G_Big == 4000000000u));
    case 5:
#line 30 1
      return ((G_Weights[0] == 1.0) && (G_Weights[2] == 4.0));
    case 6:
#line 31 1
      return ((G_Rows[1][0] == 3.0) && (G_Rows[0][1] == 2.0));
    case 7:
#line 32 1
      return (G_Unset == 0.0);
    case 8:
#line 33 1
      return (((G_Frames[0][0][2] == 3.0) && (G_Frames[1][2][0] == 16.0)) && (G_Frames[1][1][1] == 14.0));
    case 9:
#line 34 1
      return (G_Last == 0.5);
    case 10:
#line 35 1
      return ((G_IRows[1][0] == 7) && (G_IRows[0][1] == 6));
    default:
#line 36 1
      return true;
  }
}
#line 40 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 41 1
{
#line 42 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 40 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   uniforms.fx
1 of 1 files parse
