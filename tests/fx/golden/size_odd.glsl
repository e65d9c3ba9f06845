// technique size_odd pass 
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
#line 7 1
vec4 F_Fill(vec4 l_position, vec2 l_texcoord)
#line 7 1
{
#line 7 1
  return vec4(1.0);
}
#line 7 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Fill(p0, p1);
  pfx_target_0 = r;
}
// technique size_odd pass 
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
layout(binding = 1) uniform sampler2D G_SHalf;
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
#line 11 2
vec4 F_Verdict(bool l_ok)
#line 11 2
{
#line 11 2
  return (l_ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0));
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
#line 8 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 9 1
{
#line 10 1
  ivec2 l_p = ivec2(pfx_ftoi(l_position.xy));
#line 11 1
  bool l_ok = (((1920 == 28) && (1080 == 5)) && all(equal(textureSize(G_SHalf, 0), ivec2(9, 2))));
#line 12 1
  (l_ok = ((l_ok && F_SameCode(texelFetch(G_ReShade_ns_BackBuffer, pfx_flip_texel(ivec2(l_p), textureSize(G_ReShade_ns_BackBuffer, 0).y), 0).xyz, F_InputPixel(l_p))) && (texelFetch(G_SHalf, pfx_flip_texel(ivec2(ivec2(8, 1)), textureSize(G_SHalf, 0).y), 0).x == 1.0)));
#line 13 1
  return F_Verdict(l_ok);
}
#line 8 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   size_odd.fx
1 of 1 files parse
