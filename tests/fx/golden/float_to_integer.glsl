// technique float_to_integer pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  uint G_FromNegative;
  int G_FromHuge;
  uint G_FromHugeUnsigned;
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
  uint G_FromNegative;
  int G_FromHuge;
  uint G_FromHugeUnsigned;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
int pfx_ftoi(float x) { return x >= 2147483648.0 ? 2147483647 : x > -2147483648.0 ? int(x) : x < 0.0 ? (-2147483647 - 1) : 0; }
ivec2 pfx_ftoi(vec2 x) { return mix(mix(mix(ivec2(0), ivec2(-2147483647 - 1), lessThan(x, vec2(0.0))), ivec2(x), greaterThan(x, vec2(-2147483648.0))), ivec2(2147483647), greaterThanEqual(x, vec2(2147483648.0))); }
ivec3 pfx_ftoi(vec3 x) { return mix(mix(mix(ivec3(0), ivec3(-2147483647 - 1), lessThan(x, vec3(0.0))), ivec3(x), greaterThan(x, vec3(-2147483648.0))), ivec3(2147483647), greaterThanEqual(x, vec3(2147483648.0))); }
ivec4 pfx_ftoi(vec4 x) { return mix(mix(mix(ivec4(0), ivec4(-2147483647 - 1), lessThan(x, vec4(0.0))), ivec4(x), greaterThan(x, vec4(-2147483648.0))), ivec4(2147483647), greaterThanEqual(x, vec4(2147483648.0))); }
uint pfx_ftou(float x) { return x >= 4294967296.0 ? 4294967295u : x > 0.0 ? uint(x) : 0u; }
uvec2 pfx_ftou(vec2 x) { return mix(mix(uvec2(0u), uvec2(x), greaterThan(x, vec2(0.0))), uvec2(4294967295u), greaterThanEqual(x, vec2(4294967296.0))); }
uvec3 pfx_ftou(vec3 x) { return mix(mix(uvec3(0u), uvec3(x), greaterThan(x, vec3(0.0))), uvec3(4294967295u), greaterThanEqual(x, vec3(4294967296.0))); }
uvec4 pfx_ftou(vec4 x) { return mix(mix(uvec4(0u), uvec4(x), greaterThan(x, vec4(0.0))), uvec4(4294967295u), greaterThanEqual(x, vec4(4294967296.0))); }
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
#line 14 1
bool F_Check(int l_i)
#line 15 1
{
  mat2 t_0;
#line 17 1
  float l_nan = uintBitsToFloat((2143289344u + uint(G_IZero)));
  float l_inf = uintBitsToFloat((2139095040u + uint(G_IZero)));
#line 18 1
  switch (l_i) {
    case 0:
#line 20 1
      return (((pfx_ftou(((-1.0) + G_Zero)) == 0u) && (pfx_ftou(((-0.5) + G_Zero)) == 0u)) && (pfx_ftou((3.9000001 + G_Zero)) == 3u));
    case 1:
#line 21 1
      return ((pfx_ftou((1e+10 + G_Zero)) == 4294967295u) && (pfx_ftou((4.29496704e+09 + G_Zero)) == 4294967040u));
    case 2:
#line 22 1
      return (((pfx_ftoi(((-3.9000001) + G_Zero)) == (-3)) && (pfx_ftoi((1e+10 + G_Zero)) == 2147483647)) && (pfx_ftoi(((-1e+10) + G_Zero)) == ((-2147483647) - 1)));
    case 3:
#line 23 1
      return (((((pfx_ftoi(l_nan) == 0) && (pfx_ftou(l_nan) == 0u)) && (pfx_ftoi(l_inf) == 2147483647)) && (pfx_ftoi((-l_inf)) == ((-2147483647) - 1))) && (pfx_ftou(l_inf) == 4294967295u));
    case 4:
#line 24 1
      {
#line 24 1
        uint l_u = pfx_ftou(((-2.0) + G_Zero));
#line 24 1
        int l_k = pfx_ftoi((2.5e+09 + G_Zero));
#line 24 1
        return ((l_u == 0u) && (l_k == 2147483647));
      }
    case 5:
#line 25 1
      return (all(equal(uvec2(pfx_ftou((vec2((-1.0), 5.5) + vec2(G_Zero)))), uvec2(0, 5))) && all(equal(ivec3(pfx_ftoi((vec3((-1e+10), 7.9000001, l_nan) + vec3(G_Zero)))), ivec3(((-2147483647) - 1), 7, 0))));
    case 6:
#line 26 1
      {
#line 26 1
        uvec2 l_c = uvec2(pfx_ftou(((-1.0) + G_Zero)), pfx_ftou((2.0 + G_Zero)));
#line 26 1
        ivec2 l_d = ivec2(pfx_ftoi(l_nan), pfx_ftoi(((-2.5) + G_Zero)));
#line 26 1
        return (all(equal(l_c, uvec2(0, 2))) && all(equal(l_d, ivec2(0, (-2)))));
      }
    case 7:
#line 27 1
      {
#line 27 1
        uint l_a[2] = uint[2](pfx_ftou(((-1.0) + G_Zero)), pfx_ftou((7.5 + G_Zero)));
#line 27 1
        return ((l_a[0] == 0u) && (l_a[1] == 7u));
      }
    case 8:
#line 28 1
      {
#line 28 1
        ivec2[2] l_m = (t_0 = (mat2((-1e+10), 1.5, (-1.5), 1e+10) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero))), ivec2[2](pfx_ftoi(t_0[0]), pfx_ftoi(t_0[1])));
#line 28 1
        return ((((l_m[0][0] == ((-2147483647) - 1)) && (l_m[0][1] == 1)) && (l_m[1][0] == (-1))) && (l_m[1][1] == 2147483647));
      }
    case 9:
#line 29 1
      return (((G_FromNegative == 0u) && (G_FromHuge == 2147483647)) && (G_FromHugeUnsigned == 4294967295u));
    case 10:
#line 30 1
      {
#line 30 1
        uvec4 l_v = pfx_ftou((vec4((-3.0), 0.0, 65535.8984, (-0.0)) + vec4(G_Zero)));
#line 30 1
        return all(equal(l_v, uvec4(0, 0, 65535, 0)));
      }
    default:
#line 31 1
      return true;
  }
}
#line 35 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 36 1
{
#line 37 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 35 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   float_to_integer.fx
1 of 1 files parse
