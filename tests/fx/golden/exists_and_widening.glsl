// technique exists_and_widening pass 
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
#line 29 1
bool F_Check(int l_i)
#line 30 1
{
#line 31 1
  vec4 l_colour = vec4(9.0, 9.0, 9.0, 9.0);
#line 32 1
  (l_colour = vec3(0.25, 0.5, (0.75 + G_Zero)).xyzz);
#line 33 1
  vec4 l_pair = vec4(9.0, 9.0, 9.0, 9.0);
#line 34 1
  (l_pair = vec2((1.0 + G_Zero), 2.0).xyyy);
#line 35 1
  ivec3 l_whole = ivec3(9, 9, 9);
#line 36 1
  (l_whole += ivec2((1 + G_IZero), 2).xyy);
#line 37 1
  switch (l_i) {
    case 0:
#line 39 1
      return (1 == (1 + G_IZero));
    case 1:
#line 40 1
      return (1 == (1 + G_IZero));
    case 2:
#line 41 1
      return (1 == (1 + G_IZero));
    case 3:
#line 42 1
      return F_Near(l_colour, vec4(0.25, 0.5, 0.75, 0.75));
    case 4:
#line 43 1
      return F_Near(l_pair, vec4(1.0, 2.0, 2.0, 2.0));
    case 5:
#line 44 1
      return all(equal(l_whole, ivec3(10, 11, 11)));
    default:
#line 45 1
      return true;
  }
}
#line 49 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 50 1
{
#line 51 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
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
OK   exists_and_widening.fx
exists_and_widening.fx:32:12: warning: 'float3' assigned to 'float4': its last component fills the rest, as ReShade does
exists_and_widening.fx:34:10: warning: 'float2' assigned to 'float4': its last component fills the rest, as ReShade does
exists_and_widening.fx:36:12: warning: 'int2' assigned to 'int3': its last component fills the rest, as ReShade does
1 of 1 files parse
