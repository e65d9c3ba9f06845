// technique render_targets pass 
#version 450
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
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
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
};
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
layout(location = 1) out vec4 pfx_target_1;
layout(location = 2) out vec4 pfx_target_2;
layout(location = 3) out vec4 pfx_target_3;
#line 25 1
void F_WriteAll(vec4 l_position, vec2 l_texcoord, out vec4 l_a, out vec4 l_b, out S_Outputs l_rest)
#line 26 1
{
#line 27 1
  (l_a = vec4(1.0));
#line 28 1
  (l_b = vec4(2.0, 3.0, 0.0, 0.0));
#line 29 1
  (l_rest.m_c = vec4(4.0, 5.0, 6.0, 7.0));
#line 30 1
  (l_rest.m_d = vec4(0.200000003, 0.400000006, 0.600000024, 0.800000012));
}
#line 25 1
void main() {
  vec4 p0;
  vec2 p1;
  vec4 p2;
  vec4 p3;
  S_Outputs p4;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  F_WriteAll(p0, p1, p2, p3, p4);
  pfx_target_0 = p2;
  pfx_target_1 = p3;
  pfx_target_2 = p4.m_c;
  pfx_target_3 = p4.m_d;
}
// technique render_targets pass 
#version 450
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
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
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
};
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
#line 32 1
vec4 F_Fill(vec4 l_position, vec2 l_texcoord)
#line 32 1
{
#line 32 1
  return vec4(9.0);
}
#line 32 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Fill(p0, p1);
  pfx_target_0 = r;
}
// technique render_targets pass 
#version 450
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
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
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
};
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
#line 32 1
vec4 F_Fill(vec4 l_position, vec2 l_texcoord)
#line 32 1
{
#line 32 1
  return vec4(9.0);
}
#line 32 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Fill(p0, p1);
  pfx_target_0 = r;
}
// technique render_targets pass 
#version 450
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
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
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
};
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
#line 33 1
vec4 F_Skip(vec4 l_position, vec2 l_texcoord)
#line 33 1
{
#line 33 1
  discard;
#line 33 1
  return vec4(9.0);
}
#line 33 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Skip(p0, p1);
  pfx_target_0 = r;
}
// technique render_targets pass 
#version 450
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
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
struct S_Outputs {
  vec4 m_c;
  vec4 m_d;
};
layout(binding = 0) uniform sampler2D G_SFraction;
layout(binding = 1) uniform sampler2D G_SA;
layout(binding = 2) uniform sampler2D G_SB;
layout(binding = 3) uniform sampler2D G_SC;
layout(binding = 4) uniform sampler2D G_SD;
layout(binding = 5) uniform sampler2D G_SCleared;
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
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
#line 18 2
bool F_Near(vec4 l_a, vec4 l_b)
#line 18 2
{
#line 18 2
  return (F_Near(l_a.xy, l_b.xy) && F_Near(l_a.zw, l_b.zw));
}
#line 35 1
bool F_Check(int l_i)
#line 36 1
{
#line 37 1
  switch (l_i) {
    case 0:
#line 39 1
      return (((texelFetch(G_SA, pfx_flip_texel(ivec2((ivec2(2, 1) + ivec2(G_IZero))), textureSize(G_SA, 0).y), 0).x == 1.0) && (texelFetch(G_SFraction, pfx_flip_texel(ivec2((ivec2(15, 1) + ivec2(G_IZero))), textureSize(G_SFraction, 0).y), 0).x == 9.0)) && all(equal(textureSize(G_SFraction, 0), ivec2(16, 2))));
    case 1:
#line 40 1
      return all(equal(texelFetch(G_SB, pfx_flip_texel(ivec2((ivec2(2, 1) + ivec2(G_IZero))), textureSize(G_SB, 0).y), 0).xy, vec2(2.0, 3.0)));
    case 2:
#line 41 1
      return all(equal(texelFetch(G_SC, pfx_flip_texel(ivec2((ivec2(1, 0) + ivec2(G_IZero))), textureSize(G_SC, 0).y), 0), vec4(4.0, 5.0, 6.0, 7.0)));
    case 3:
#line 42 1
      return F_Near(texelFetch(G_SD, pfx_flip_texel(ivec2((ivec2(2, 0) + ivec2(G_IZero))), textureSize(G_SD, 0).y), 0), (vec4(51, 102, 153, 204) / vec4(255.0)));
    case 4:
#line 43 1
      return (texelFetch(G_SCleared, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SCleared, 0).y), 0).x == 0.0);
    default:
#line 44 1
      return true;
  }
}
#line 48 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 49 1
{
#line 50 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 48 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   render_targets.fx
1 of 1 files parse
