// technique intrinsics_bits pass 
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
float pfx_f16tof32(uint x) { return unpackHalf2x16(x).x; }
vec2 pfx_f16tof32(uvec2 x) { return vec2(pfx_f16tof32(x.x), pfx_f16tof32(x.y)); }
vec3 pfx_f16tof32(uvec3 x) { return vec3(pfx_f16tof32(x.xy), pfx_f16tof32(x.z)); }
vec4 pfx_f16tof32(uvec4 x) { return vec4(pfx_f16tof32(x.xy), pfx_f16tof32(x.zw)); }
uint pfx_f32tof16(float x) { return packHalf2x16(vec2(x, 0.0)) & 0xFFFFu; }
uvec2 pfx_f32tof16(vec2 x) { return uvec2(pfx_f32tof16(x.x), pfx_f32tof16(x.y)); }
uvec3 pfx_f32tof16(vec3 x) { return uvec3(pfx_f32tof16(x.xy), pfx_f32tof16(x.z)); }
uvec4 pfx_f32tof16(vec4 x) { return uvec4(pfx_f32tof16(x.xy), pfx_f32tof16(x.zw)); }
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
#line 5 1
bool F_Check(int l_i)
#line 6 1
{
#line 7 1
  uint l_u = uint(G_IZero);
#line 8 1
  switch (l_i) {
    case 0:
#line 10 1
      return (uint(bitCount((61680u + l_u))) == 8u);
    case 1:
#line 11 1
      return (bitfieldReverse((1u + l_u)) == 2147483648u);
    case 2:
#line 12 1
      return ((uint(findMSB((240u + l_u))) == 7u) && (uint(findLSB((240u + l_u))) == 4u));
    case 3:
#line 13 1
      return ((floatBitsToUint((1.0 + G_Zero)) == 1065353216u) && (uintBitsToFloat((1073741824u + l_u)) == 2.0));
    case 4:
#line 14 1
      return ((floatBitsToInt(((-2.0) + G_Zero)) == int(3221225472u)) && (intBitsToFloat(floatBitsToInt((0.25 + G_Zero))) == 0.25));
    case 5:
#line 15 1
      return ((pfx_f32tof16((1.0 + G_Zero)) == 15360u) && (pfx_f16tof32((49152u + l_u)) == (-2.0)));
    case 6:
#line 16 1
      return (((((240u + l_u) & 60u) == 48u) && (((240u + l_u) | 15u) == 255u)) && (((240u + l_u) ^ 255u) == 15u));
    case 7:
#line 17 1
      return (((((1 + G_IZero) << 4) == 16) && ((((-16) + G_IZero) >> 2) == (-4))) && (((2147483648u + l_u) >> uint(31)) == 1u));
    case 8:
#line 18 1
      return (((~(0 + G_IZero)) == (-1)) && ((~(0u + l_u)) == 4294967295u));
    case 9:
#line 19 1
      return all(equal(uvec2(bitCount((uvec2(3u, 7u) + uvec2(l_u)))), uvec2(2u, 3u)));
    case 10:
#line 20 1
      return (floatBitsToUint((-G_Zero)) == 2147483648u);
    case 11:
#line 21 1
      return ((pfx_f16tof32(pfx_f32tof16((0.5 + G_Zero))) == 0.5) && (pfx_f32tof16((65504.0 + G_Zero)) == 31743u));
    default:
#line 22 1
      return true;
  }
}
#line 26 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 27 1
{
#line 28 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 26 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   intrinsics_bits.fx
1 of 1 files parse
