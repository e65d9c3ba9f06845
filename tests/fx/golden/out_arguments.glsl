// technique out_arguments pass 
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
#line 9 1
void F_SetHalves(out float l_x)
#line 9 1
{
#line 9 1
  (l_x = (2.5 + G_Zero));
}
#line 10 1
void F_Double(inout float l_x)
#line 10 1
{
#line 10 1
  (l_x = (l_x * 2.0));
}
#line 11 1
void F_Negate(inout int l_x)
#line 11 1
{
#line 11 1
  (l_x = (-l_x));
}
#line 12 1
float F_IncrementAndOld(inout float l_x)
#line 12 1
{
#line 12 1
  float l_old = l_x;
#line 12 1
  (l_x += 1.75);
#line 12 1
  return l_old;
}
#line 13 1
void F_SetPair(out vec2 l_p)
#line 13 1
{
#line 13 1
  (l_p = (vec2(7.0, 8.0) + vec2(G_Zero)));
}
#line 14 1
void F_Swap(inout float l_a, inout float l_b)
#line 14 1
{
#line 14 1
  float l_t = l_a;
#line 14 1
  (l_a = l_b);
#line 14 1
  (l_b = l_t);
}
#line 16 1
bool F_Check(int l_i)
#line 17 1
{
  float t_0;
  float t_1;
  int t_2;
  float t_3;
  float t_4;
  vec2 t_5;
  vec2 t_6;
  float t_7;
  float t_8;
#line 18 1
  mat2 l_m = (mat2(1, 2, 3, 4) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 19 1
  switch (l_i) {
    case 0:
#line 21 1
      {
#line 21 1
        int l_k = (3 + G_IZero);
#line 21 1
        (F_SetHalves(t_0), (l_k = pfx_ftoi(t_0)));
#line 21 1
        return (l_k == 2);
      }
    case 1:
#line 22 1
      {
#line 22 1
        int l_k = ((-3) + G_IZero);
#line 22 1
        (t_1 = float(l_k), F_Double(t_1), (l_k = pfx_ftoi(t_1)));
#line 22 1
        return (l_k == (-6));
      }
    case 2:
#line 23 1
      {
#line 23 1
        float l_f = (2.75 + G_Zero);
#line 23 1
        (t_2 = pfx_ftoi(l_f), F_Negate(t_2), (l_f = float(t_2)));
#line 23 1
        return (l_f == (-2.0));
      }
    case 3:
#line 24 1
      {
#line 24 1
        uint l_u = (5u + uint(G_IZero));
#line 24 1
        float l_old = (t_3 = float(l_u), t_4 = F_IncrementAndOld(t_3), (l_u = pfx_ftou(t_3)), t_4);
#line 24 1
        return ((l_old == 5.0) && (l_u == 6u));
      }
    case 4:
#line 25 1
      {
#line 25 1
        float l_f = (1.5 + G_Zero);
#line 25 1
        float l_old = F_IncrementAndOld(l_f);
#line 25 1
        return ((l_old == 1.5) && (l_f == 3.25));
      }
    case 5:
#line 26 1
      {
#line 26 1
        mat2 l_a = l_m;
#line 26 1
        F_SetHalves(l_a[1][1]);
#line 26 1
        return ((l_a[1][1] == 2.5) && (l_a[1][0] == 3.0));
      }
    case 6:
#line 27 1
      {
#line 27 1
        mat2 l_a = l_m;
#line 27 1
        (F_SetPair(t_5), (t_6 = t_5, l_a[0][1] = t_6[0], l_a[1][0] = t_6[1], t_6));
#line 27 1
        return ((((l_a[0][1] == 7.0) && (l_a[1][0] == 8.0)) && (l_a[0][0] == 1.0)) && (l_a[1][1] == 4.0));
      }
    case 7:
#line 28 1
      {
#line 28 1
        mat2 l_a = l_m;
#line 28 1
        F_Swap(l_a[0][0], l_a[1][1]);
#line 28 1
        return ((l_a[0][0] == 4.0) && (l_a[1][1] == 1.0));
      }
    case 8:
#line 29 1
      {
#line 29 1
        ivec2 l_v = (ivec2(3, 9) + ivec2(G_IZero));
#line 29 1
        (t_7 = float(l_v.y), F_Double(t_7), (l_v.y = pfx_ftoi(t_7)));
#line 29 1
        return ((l_v.x == 3) && (l_v.y == 18));
      }
    case 9:
#line 30 1
      {
#line 30 1
        bool l_b = (G_IZero == 0);
#line 30 1
        (t_8 = float(l_b), F_Double(t_8), (l_b = bool(t_8)));
#line 30 1
        return l_b;
      }
    case 10:
#line 31 1
      {
#line 31 1
        float l_r = (F_IncrementAndOld(l_m[0][0]) + F_IncrementAndOld(l_m[0][0]));
#line 31 1
        return ((l_r == 3.75) && (l_m[0][0] == 4.5));
      }
    default:
#line 32 1
      return true;
  }
}
#line 36 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 37 1
{
#line 38 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 36 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   out_arguments.fx
1 of 1 files parse
