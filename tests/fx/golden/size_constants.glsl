// technique size_constants pass 
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
layout(binding = 0) uniform sampler2D G_Swizzled;
layout(binding = 1) uniform sampler2D G_Floats;
layout(binding = 2) uniform sampler2D G_Frame;
layout(binding = 3) uniform sampler2D G_Mipped;
layout(binding = 4) uniform sampler2D G_Vanished;
int G_Levels;
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
#line 27 1
bool F_Check(int l_i)
#line 28 1
{
#line 29 1
  switch (l_i) {
    case 0:
#line 31 1
      return all(equal(textureSize(G_Swizzled, int(0)), ivec2(8, 4)));
    case 1:
#line 32 1
      return all(equal(textureSize(G_Floats, int(0)), ivec2(12, 6)));
    case 2:
#line 33 1
      return all(equal(textureSize(G_Frame, int(0)), ivec2(21, 3)));
    case 3:
#line 34 1
      return (all(equal(textureSize(G_Mipped, int(0)), ivec2(16, 16))) && (G_Levels == 5));
    case 4:
#line 35 1
      return all(equal(textureSize(G_Mipped, int(4)), ivec2(1, 1)));
    case 5:
#line 36 1
      return all(equal(textureSize(G_Vanished, int(0)), ivec2(1, 1)));
    default:
#line 37 1
      return true;
  }
}
#line 41 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 42 1
{
#line 43 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 41 1
void main() {
  G_Levels = (((((int(((16 >> 1) != 0)) + int(((16 >> 2) != 0))) + int(((16 >> 3) != 0))) + int(((16 >> 4) != 0))) + int(((16 >> 5) != 0))) + 1);
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   size_constants.fx
size_constants.fx:24:109: warning: 'MipLevels' is 0 at this frame size; 1 is used, as ReShade does
1 of 1 files parse
