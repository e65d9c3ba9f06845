// technique reshade_language pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  int G_Mode;
};
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
  uint p0;
  vec4 p1;
  vec2 p2;
  p0 = uint(gl_VertexID);
  F_PostProcessVS(p0, p1, p2);
  gl_Position = p1;
}
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  int G_Mode;
};
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
#line 24 1
vec4 F_Fill(vec4 l_position)
#line 24 1
{
#line 24 1
  return vec4(0.5, 0.5, 0.5, 1.0);
}
#line 24 1
void main() {
  vec4 p0;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  vec4 r = F_Fill(p0);
  pfx_target_0 = r;
}
// technique reshade_language pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  int G_Mode;
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
layout(binding = 0) uniform sampler2D G_LinearSampler;
layout(binding = 1) uniform sampler2D G_SrgbSampler;
vec4 G_Tint1;
vec4 G_Tint2;
mat3 G_Scale;
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  int G_Mode;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
vec2 pfx_flip(vec2 c) { return vec2(c.x, 1.0 - c.y); }
vec3 pfx_flip(vec3 c) { return vec3(c.x, 1.0 - c.y, c.z); }
ivec2 pfx_flip_texel(ivec2 c, int h) { return ivec2(c.x, h - 1 - c.y); }
ivec3 pfx_flip_texel(ivec3 c, int h) { return ivec3(c.x, h - 1 - c.y, c.z); }
vec2 pfx_flip_offset(vec2 o) { return vec2(o.x, -o.y); }
vec3 pfx_flip_offset(vec3 o) { return vec3(o.x, -o.y, o.z); }
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
#line 16 1
vec3 F_Scale(vec3 l_c)
#line 16 1
{
#line 16 1
  return (l_c * G_Scale);
}
#line 26 1
bool F_Check(int l_i)
#line 27 1
{
#line 28 1
  switch (l_i) {
    case 0:
#line 30 1
      return F_Near((G_Tint1.xyz + vec3(G_Zero)), vec3(0.25, 0.5, 0.75));
    case 1:
#line 31 1
      return F_Near((G_Tint2.xyz + vec3(G_Zero)), vec3(1.0, 0.0, 0.5));
    case 2:
#line 32 1
      return F_Near((texture(G_LinearSampler, pfx_flip(vec2(vec2(0.25, 0.25)))).x + G_Zero), (128.0 / 255.0));
    case 3:
#line 33 1
      return F_Close((texture(G_SrgbSampler, pfx_flip(vec2(vec2(0.75, 0.75)))).y + G_Zero), 0.215859994);
    case 4:
#line 34 1
      return ((G_Mode + G_IZero) == 0);
    case 5:
#line 35 1
      return (F_Near(F_Scale((vec3(1, 2, 3) + vec3(G_Zero))), vec3(2, 6, 12)) && F_Near((G_Scale[1][1] + G_Zero), 3.0));
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
  G_Tint1 = vec4(0.25, 0.5, 0.75, 1.0);
  G_Tint2 = vec4(1.0, 0.0, 0.5, 1.0);
  G_Scale = mat3(2, 0, 0, 0, 3, 0, 0, 0, 4);
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   reshade_language.fx
reshade_language.fx:30:25: warning: pasting "Tint1" and "." does not give a valid token: kept as they are
reshade_language.fx:31:25: warning: pasting "Tint2" and "." does not give a valid token: kept as they are
1 of 1 files parse
