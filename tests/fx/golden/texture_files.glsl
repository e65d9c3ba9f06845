// technique texture_files pass 
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
layout(binding = 0) uniform sampler2D G_SFile;
layout(binding = 1) uniform sampler2D G_SLinear;
layout(binding = 2) uniform sampler2D G_SHalf;
layout(binding = 3) uniform sampler2D G_SFloat;
layout(binding = 4) uniform sampler2D G_SMips;
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
int pfx_imod(int x, int y) { return x - y * (x / y); }
ivec2 pfx_imod(ivec2 x, ivec2 y) { return x - y * (x / y); }
ivec3 pfx_imod(ivec3 x, ivec3 y) { return x - y * (x / y); }
ivec4 pfx_imod(ivec4 x, ivec4 y) { return x - y * (x / y); }
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
#line 21 1
bool F_Code(vec4 l_seen, vec4 l_codes)
#line 21 1
{
#line 21 1
  return all(lessThanEqual(abs(((l_seen * vec4(255.0)) - l_codes)), vec4(0.5)));
}
#line 22 1
bool F_Within(vec4 l_seen, vec4 l_codes, float l_codes_off)
#line 22 1
{
#line 22 1
  return all(lessThanEqual(abs(((l_seen * vec4(255.0)) - l_codes)), vec4(l_codes_off)));
}
#line 24 1
bool F_Check(int l_i)
#line 25 1
{
#line 26 1
  ivec2 l_p = ivec2((G_IZero + pfx_imod(l_i, 4)), (G_IZero + (l_i / 4)));
#line 27 1
  switch (l_i) {
    case 0:
#line 29 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(10, 20, 30, 255));
    case 1:
#line 30 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(40, 50, 60, 200));
    case 2:
#line 31 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(70, 80, 90, 150));
    case 3:
#line 32 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(100, 110, 120, 100));
    case 4:
#line 33 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(130, 140, 150, 50));
    case 5:
#line 34 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(160, 170, 180, 25));
    case 6:
#line 35 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(190, 200, 210, 5));
    case 7:
#line 36 1
      return F_Code(texelFetch(G_SFile, pfx_flip_texel(ivec2(l_p), textureSize(G_SFile, 0).y), 0), vec4(220, 230, 240, 0));
    case 8:
#line 37 1
      return (F_Code(texelFetch(G_SHalf, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SHalf, 0).y), 0), vec4(10, 20, 30, 255)) && F_Code(texelFetch(G_SHalf, pfx_flip_texel(ivec2((ivec2(1, 0) + ivec2(G_IZero))), textureSize(G_SHalf, 0).y), 0), vec4(70, 80, 90, 150)));
    case 9:
#line 39 1
      return (abs((texelFetch(G_SFloat, pfx_flip_texel(ivec2((ivec2(3, 1) + ivec2(G_IZero))), textureSize(G_SFloat, 0).y), 0).x - (220.0 / 255.0))) <= 0.00100000005);
    case 10:
#line 41 1
      return F_Within(textureLod(G_SLinear, pfx_flip(vec2((vec4(0.25, 0.25, 0.0, 0.0)).xy)), (vec4(0.25, 0.25, 0.0, 0.0)).w), vec4(25, 35, 45, 227.5), 1.0);
    case 11:
#line 43 1
      return F_Within(textureLod(G_SMips, pfx_flip(vec2((vec4(0.25, 0.5, 0.0, 1.0)).xy)), (vec4(0.25, 0.5, 0.0, 1.0)).w), vec4(85, 95, 105, 132.5), 1.0);
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
OK   texture_files.fx
1 of 1 files parse
