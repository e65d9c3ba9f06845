// technique textures pass 
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
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
#line 13 1
vec4 F_FillGrid(vec4 l_position, vec2 l_texcoord)
#line 14 1
{
#line 15 1
  vec2 l_p = floor(l_position.xy);
#line 16 1
  return vec4(l_p.x, l_p.y, (l_p.x + (10.0 * l_p.y)), 1.0);
}
#line 13 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_FillGrid(p0, p1);
  pfx_target_0 = r;
}
// technique textures pass 
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
layout(binding = 0) uniform sampler2D G_ReShade_ns_BackBuffer;
layout(binding = 1) uniform sampler2D G_GridPoint;
layout(binding = 2) uniform sampler2D G_GridLinear;
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
#line 15 2
bool F_Near(float l_a, float l_b)
#line 15 2
{
#line 15 2
  return (abs((l_a - l_b)) <= (9.99999975e-06 * max(1.0, abs(l_b))));
}
#line 3 4
vec3 F_InputPixel(ivec2 l_p)
#line 4 4
{
#line 5 4
  return (vec3(pfx_imod(((l_p.x * 37) + (l_p.y * 11)), 256), pfx_imod(((l_p.x * 5) + (l_p.y * 67)), 256), pfx_imod(((l_p.x * 3) + 128), 256)) / vec3(255.0));
}
#line 8 4
bool F_SameCode(vec3 l_a, vec3 l_b)
#line 8 4
{
#line 8 4
  return all(lessThanEqual(abs((l_a - l_b)), vec3((0.5 / 255.0))));
}
#line 19 1
vec2 F_Centre(ivec2 l_texel)
#line 19 1
{
#line 19 1
  return ((vec2(l_texel) + vec2(0.5)) / vec2(8.0, 4.0));
}
#line 21 1
bool F_Check(int l_i)
#line 22 1
{
#line 23 1
  vec4 l_g;
#line 24 1
  switch (l_i) {
    case 0:
#line 26 1
      return all(equal(texelFetch(G_GridPoint, pfx_flip_texel(ivec2((ivec2(3, 1) + ivec2(G_IZero))), textureSize(G_GridPoint, 0).y), 0), vec4(3, 1, 13, 1)));
    case 1:
#line 27 1
      return all(equal(texture(G_GridPoint, pfx_flip(vec2((F_Centre(ivec2(5, 2)) + vec2(G_Zero))))), vec4(5, 2, 25, 1)));
    case 2:
#line 28 1
      return all(equal(textureLod(G_GridLinear, pfx_flip(vec2(((vec4(F_Centre(ivec2(6, 3)), 0, 0) + vec4(G_Zero))).xy)), ((vec4(F_Centre(ivec2(6, 3)), 0, 0) + vec4(G_Zero))).w), vec4(6, 3, 36, 1)));
    case 3:
#line 29 1
      return (all(equal(textureSize(G_GridPoint, 0), ivec2(8, 4))) && all(equal(textureSize(G_GridPoint, int(0)), ivec2(8, 4))));
    case 4:
#line 32 1
      (l_g = (textureGather(G_GridPoint, pfx_flip(vec2((vec2((2.0 / 8.0), (2.0 / 4.0)) + vec2(G_Zero)))), 0)).xyzw.wzyx);
#line 32 1
      return all(equal(l_g, vec4(1, 2, 2, 1)));
    case 5:
#line 33 1
      (l_g = (textureGather(G_GridPoint, pfx_flip(vec2((vec2((2.0 / 8.0), (2.0 / 4.0)) + vec2(G_Zero)))), 1)).xyzw.wzyx);
#line 33 1
      return all(equal(l_g, vec4(2, 2, 1, 1)));
    case 6:
#line 34 1
      (l_g = (textureGather(G_GridPoint, pfx_flip(vec2((vec2((2.0 / 8.0), (2.0 / 4.0)) + vec2(G_Zero)))), 0)).xyzw.wzyx);
#line 34 1
      return all(equal(l_g, vec4(1, 2, 2, 1)));
    case 7:
#line 35 1
      return all(equal(textureOffset(G_GridPoint, pfx_flip(vec2((F_Centre(ivec2(2, 1)) + vec2(G_Zero)))), ivec2(1, -1)), vec4(3, 2, 23, 1)));
    case 8:
#line 36 1
      return all(equal(textureOffset(G_GridPoint, pfx_flip(vec2((F_Centre(ivec2(2, 1)) + vec2(G_Zero)))), ivec2(-1, -2)), vec4(1, 3, 31, 1)));
    case 9:
#line 37 1
      return all(equal(textureGrad(G_GridPoint, pfx_flip(vec2((F_Centre(ivec2(4, 0)) + vec2(G_Zero)))), pfx_flip_offset(vec2(vec2(0, 0))), pfx_flip_offset(vec2(vec2(0, 0)))), vec4(4, 0, 4, 1)));
    case 10:
#line 38 1
      return all(equal(texture(G_GridPoint, pfx_flip(vec2(((vec4(F_Centre(ivec2(7, 3)), 0, 0) + vec4(G_Zero))).xy)), ((vec4(F_Centre(ivec2(7, 3)), 0, 0) + vec4(G_Zero))).w), vec4(7, 3, 37, 1)));
    case 11:
#line 39 1
      return all(equal(texture(G_GridPoint, pfx_flip(vec2(((vec4((F_Centre(ivec2(1, 2)) * vec2(2.0)), 0, 2) + vec4(G_Zero))).xy / ((vec4((F_Centre(ivec2(1, 2)) * vec2(2.0)), 0, 2) + vec4(G_Zero))).w))), vec4(1, 2, 21, 1)));
    case 12:
#line 40 1
      return F_Near(texture(G_GridLinear, pfx_flip(vec2((vec2((2.0 / 8.0), (0.5 / 4.0)) + vec2(G_Zero))))).x, 1.5);
    case 13:
#line 42 1
      return F_SameCode(texelFetch(G_ReShade_ns_BackBuffer, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_ReShade_ns_BackBuffer, 0).y), 0).xyz, F_InputPixel(ivec2(0, 0)));
    case 14:
#line 43 1
      return F_SameCode(texelFetch(G_ReShade_ns_BackBuffer, pfx_flip_texel(ivec2((ivec2(5, 1) + ivec2(G_IZero))), textureSize(G_ReShade_ns_BackBuffer, 0).y), 0).xyz, F_InputPixel(ivec2(5, 1)));
    case 15:
#line 44 1
      return F_SameCode(texture(G_ReShade_ns_BackBuffer, pfx_flip(vec2((((vec2(9, 3) + vec2(0.5)) / vec2(64, 4)) + vec2(G_Zero))))).xyz, F_InputPixel(ivec2(9, 3)));
    default:
#line 45 1
      return true;
  }
}
#line 49 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 50 1
{
#line 52 1
  bool l_agree = all(lessThan(abs(((l_texcoord * vec2(64, 4)) - l_position.xy)), vec2(0.00999999978)));
#line 53 1
  return F_Verdict((l_agree && F_Check(F_CheckIndex(l_position))));
}
#line 49 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   textures.fx
1 of 1 files parse
