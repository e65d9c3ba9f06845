// technique conversions pass 
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
#line 6 1
float F_TakesFloat(float l_x)
#line 6 1
{
#line 6 1
  return l_x;
}
#line 7 1
int F_TakesInt(int l_x)
#line 7 1
{
#line 7 1
  return l_x;
}
#line 8 1
vec2 F_ReturnsTruncated()
#line 8 1
{
#line 8 1
  return vec2((vec4(1, 2, 3, 4) + vec4(G_Zero)));
}
#line 10 1
bool F_Check(int l_i)
#line 11 1
{
#line 12 1
  switch (l_i) {
    case 0:
#line 14 1
      {
#line 14 1
        vec2 l_t = vec2((vec4(1, 2, 3, 4) + vec4(G_Zero)));
#line 14 1
        return all(equal(l_t, vec2(1, 2)));
      }
    case 1:
#line 15 1
      {
#line 15 1
        vec4 l_s = vec4((2.0 + G_Zero));
#line 15 1
        return all(equal(l_s, vec4(2, 2, 2, 2)));
      }
    case 2:
#line 16 1
      {
#line 16 1
        int l_a = pfx_ftoi((2.70000005 + G_Zero));
#line 16 1
        int l_b = pfx_ftoi(((-2.70000005) + G_Zero));
#line 16 1
        return ((l_a == 2) && (l_b == (-2)));
      }
    case 3:
#line 17 1
      {
#line 17 1
        uint l_u = pfx_ftou((3.9000001 + G_Zero));
#line 17 1
        return (l_u == 3u);
      }
    case 4:
#line 18 1
      {
#line 18 1
        bool l_b = bool((0.5 + G_Zero));
#line 18 1
        bool l_z = bool(G_Zero);
#line 18 1
        return (l_b && (!l_z));
      }
    case 5:
#line 19 1
      {
#line 19 1
        float l_f = float((true && (G_Zero == 0.0)));
#line 19 1
        int l_k = int((G_Zero == 0.0));
#line 19 1
        return ((l_f == 1.0) && (l_k == 1));
      }
    case 6:
#line 20 1
      return ((F_TakesFloat(float((3 + G_IZero))) == 3.0) && (F_TakesInt(pfx_ftoi((3.9000001 + G_Zero))) == 3));
    case 7:
#line 21 1
      return all(equal(F_ReturnsTruncated(), vec2(1, 2)));
    case 8:
#line 22 1
      {
#line 22 1
        vec3 l_v = (vec3(1, 2, 3) + vec3(G_IZero));
#line 22 1
        return all(equal((l_v * vec3(2)), vec3(2, 4, 6)));
      }
    case 9:
#line 23 1
      {
#line 23 1
        ivec2 l_v = pfx_ftoi((vec2((-1.5), 2.5) + vec2(G_Zero)));
#line 23 1
        return all(equal(l_v, ivec2((-1), 2)));
      }
    case 10:
#line 24 1
      {
#line 24 1
        uint l_u = uint(((-1) + G_IZero));
#line 24 1
        return (l_u == 4294967295u);
      }
    case 11:
#line 25 1
      {
#line 25 1
        vec4 l_v = (vec3(1, 2, 3).xyzz + vec4(G_Zero));
#line 25 1
        float l_x = (l_v).x;
#line 25 1
        return (l_x == 1.0);
      }
    default:
#line 26 1
      return true;
  }
}
#line 30 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 31 1
{
#line 32 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 30 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   conversions.fx
conversions.fx:8:55: warning: implicit truncation from 'float4' to 'float2'
conversions.fx:14:45: warning: implicit truncation from 'float4' to 'float2'
conversions.fx:25:66: warning: implicit truncation from 'float4' to 'float'
1 of 1 files parse
