// technique offsets_and_labels pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
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
};
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
int pfx_ftoi(float x) { return x >= 2147483648.0 ? 2147483647 : x > -2147483648.0 ? int(x) : x < 0.0 ? (-2147483647 - 1) : 0; }
ivec2 pfx_ftoi(vec2 x) { return mix(mix(mix(ivec2(0), ivec2(-2147483647 - 1), lessThan(x, vec2(0.0))), ivec2(x), greaterThan(x, vec2(-2147483648.0))), ivec2(2147483647), greaterThanEqual(x, vec2(2147483648.0))); }
ivec3 pfx_ftoi(vec3 x) { return mix(mix(mix(ivec3(0), ivec3(-2147483647 - 1), lessThan(x, vec3(0.0))), ivec3(x), greaterThan(x, vec3(-2147483648.0))), ivec3(2147483647), greaterThanEqual(x, vec3(2147483648.0))); }
ivec4 pfx_ftoi(vec4 x) { return mix(mix(mix(ivec4(0), ivec4(-2147483647 - 1), lessThan(x, vec4(0.0))), ivec4(x), greaterThan(x, vec4(-2147483648.0))), ivec4(2147483647), greaterThanEqual(x, vec4(2147483648.0))); }
#line 16 1
vec4 F_Fill(vec4 l_position)
#line 17 1
{
#line 18 1
  return vec4((float((pfx_ftoi(l_position.x) + (4 * pfx_ftoi(l_position.y)))) / 16.0));
}
#line 16 1
void main() {
  vec4 p0;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  vec4 r = F_Fill(p0);
  pfx_target_0 = r;
}
// technique offsets_and_labels pass 
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
layout(binding = 0) uniform sampler2D G_Grid;
ivec2 G_Shift;
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
#line 21 1
vec2 F_Center(int l_x, int l_y)
#line 21 1
{
#line 21 1
  return ((vec2(l_x, l_y) + vec2(0.5)) / vec2(4.0));
}
#line 23 1
int F_Pick(int l_mode)
#line 24 1
{
#line 25 1
  switch (l_mode) {
    case 3:
#line 27 1
      return 10;
    case 7:
#line 28 1
      return 20;
    default:
#line 29 1
      return 30;
  }
}
#line 33 1
int F_PickUnsigned(uint l_value)
#line 34 1
{
#line 35 1
  switch (l_value) {
    case 5u:
#line 37 1
      return 1;
    case 6u:
#line 38 1
      return 2;
    default:
#line 39 1
      return 0;
  }
}
#line 43 1
bool F_Check(int l_i)
#line 44 1
{
#line 45 1
  switch (l_i) {
    case 0:
#line 47 1
      return F_Near(textureOffset(G_Grid, pfx_flip(vec2(F_Center(1, 1))), ivec2(1, -2)).x, (14.0 / 16.0));
    case 1:
#line 48 1
      return F_Near(texture(G_Grid, (pfx_flip(vec2(F_Center(1, 1))) + vec2(vec2(ivec2((1 + G_IZero), (2 - G_IZero))).x, -(vec2(ivec2((1 + G_IZero), (2 - G_IZero))).y)) / vec2(textureSize(G_Grid, 0)))).x, (14.0 / 16.0));
    case 2:
#line 49 1
      return F_Near(textureOffset(G_Grid, pfx_flip(vec2(F_Center(2, 1))), ivec2(-1, -1)).x, (9.0 / 16.0));
    case 3:
#line 50 1
      return F_Near(textureLod(G_Grid, (pfx_flip(vec2((vec4(F_Center(0, 0), 0, 0)).xy)) + vec2(vec2((ivec2(3, 3) + ivec2(G_IZero))).x, -(vec2((ivec2(3, 3) + ivec2(G_IZero))).y)) / vec2(textureSize(G_Grid, int((vec4(F_Center(0, 0), 0, 0)).w)))), (vec4(F_Center(0, 0), 0, 0)).w).x, (15.0 / 16.0));
    case 4:
#line 51 1
      return F_Near(texture(G_Grid, (pfx_flip(vec2(F_Center(3, 0))) + vec2(vec2(ivec2(((-3) - G_IZero), 1)).x, -(vec2(ivec2(((-3) - G_IZero), 1)).y)) / vec2(textureSize(G_Grid, 0)))).x, (4.0 / 16.0));
    case 5:
#line 52 1
      return (((F_Pick((3 + G_IZero)) == 10) && (F_Pick((7 + G_IZero)) == 20)) && (F_Pick(G_IZero) == 30));
    case 6:
#line 53 1
      return (((F_PickUnsigned(uint((5 + G_IZero))) == 1) && (F_PickUnsigned(uint((6 + G_IZero))) == 2)) && (F_PickUnsigned(uint(G_IZero)) == 0));
    default:
#line 54 1
      return true;
  }
}
#line 58 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 59 1
{
#line 60 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 58 1
void main() {
  G_Shift = ivec2((-1), 1);
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   offsets_and_labels.fx
1 of 1 files parse
