// technique operators pass 
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
float pfx_fmod(float x, float y) { return x - y * trunc(x / y); }
vec2 pfx_fmod(vec2 x, vec2 y) { return x - y * trunc(x / y); }
vec3 pfx_fmod(vec3 x, vec3 y) { return x - y * trunc(x / y); }
vec4 pfx_fmod(vec4 x, vec4 y) { return x - y * trunc(x / y); }
int pfx_imod(int x, int y) { return x - y * (x / y); }
ivec2 pfx_imod(ivec2 x, ivec2 y) { return x - y * (x / y); }
ivec3 pfx_imod(ivec3 x, ivec3 y) { return x - y * (x / y); }
ivec4 pfx_imod(ivec4 x, ivec4 y) { return x - y * (x / y); }
bvec2 pfx_and(bvec2 a, bvec2 b) { return bvec2(ivec2(a) & ivec2(b)); }
bvec3 pfx_and(bvec3 a, bvec3 b) { return bvec3(ivec3(a) & ivec3(b)); }
bvec4 pfx_and(bvec4 a, bvec4 b) { return bvec4(ivec4(a) & ivec4(b)); }
bvec2 pfx_or(bvec2 a, bvec2 b) { return bvec2(ivec2(a) | ivec2(b)); }
bvec3 pfx_or(bvec3 a, bvec3 b) { return bvec3(ivec3(a) | ivec3(b)); }
bvec4 pfx_or(bvec4 a, bvec4 b) { return bvec4(ivec4(a) | ivec4(b)); }
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
#line 7 1
bool F_Check(int l_i)
#line 8 1
{
#line 9 1
  int l_n = ((-7) + G_IZero);
#line 10 1
  switch (l_i) {
    case 0:
#line 12 1
      return ((((l_n / 2) == (-3)) && (pfx_imod(l_n, 2) == (-1))) && (pfx_imod((7 + G_IZero), (-2)) == 1));
    case 1:
#line 13 1
      return (F_Near(pfx_fmod(((-5.5) + G_Zero), 2.0), (-1.5)) && F_Near(pfx_fmod((5.5 + G_Zero), (-2.0)), 1.5));
    case 2:
#line 14 1
      return (((((2 + (3 * 4)) + G_IZero) == 14) && ((1 << ((2 + 1) + G_IZero)) == 8)) && ((((6 & 3) | 8) + G_IZero) == 10));
    case 3:
#line 15 1
      return ((((bool((int(true) + G_IZero)) ? 2 : (3 + 1)) == 2) && ((((-2) * (-3)) + G_IZero) == 6)) && (!((1 + G_IZero) > 2)));
    case 4:
#line 16 1
      return all(equal(lessThan((vec2(1, 3) + vec2(G_Zero)), vec2(2, 2)), bvec2(true, false)));
    case 5:
#line 17 1
      return (all(equal(pfx_and(bvec2(true, false), bvec2(true, true)), bvec2(true, false))) && all(equal(pfx_or(bvec2(true, false), bvec2(false, false)), bvec2(true, false))));
    case 6:
#line 18 1
      return all(equal(mix(vec2(20, 20), vec2(10, 10), greaterThan((vec2(1, (-1)) + vec2(G_Zero)), vec2(0))), vec2(10, 20)));
    case 7:
#line 19 1
      {
#line 19 1
        int l_a = (5 + G_IZero);
#line 19 1
        (l_a += 3);
#line 19 1
        (l_a *= 2);
#line 19 1
        (l_a -= 1);
#line 19 1
        (l_a /= 3);
#line 19 1
        if ((l_a != 5))
#line 19 1
          return false;
#line 19 1
        (l_a = pfx_imod(l_a, 3));
#line 19 1
        (l_a <<= 2);
#line 19 1
        (l_a |= 1);
#line 19 1
        return (l_a == 9);
      }
    case 8:
#line 20 1
      {
#line 20 1
        int l_b = (1 + G_IZero);
#line 20 1
        (l_b++);
#line 20 1
        (++l_b);
#line 20 1
        (l_b--);
#line 20 1
        return ((l_b == 2) && ((-l_b) == (-2)));
      }
    case 9:
#line 21 1
      {
#line 21 1
        float l_f = (1.5 + G_Zero);
#line 21 1
        (l_f *= 2.0);
#line 21 1
        (l_f -= 0.5);
#line 21 1
        (l_f /= 2.0);
#line 21 1
        return (l_f == 1.25);
      }
    case 10:
#line 22 1
      {
#line 22 1
        float l_x = (2.0 + G_Zero);
#line 22 1
        vec4 l_v = (vec4(1, 2, 3, 4) + vec4(G_Zero));
#line 22 1
        return (((all(equal(vec3(l_x), vec3(2, 2, 2))) && (l_v.wzyx.x == 4.0)) && (l_v.wx.y == 1.0)) && all(equal(l_v.zy, vec2(3, 2))));
      }
    case 11:
#line 23 1
      {
#line 23 1
        vec4 l_v = (vec4(1, 2, 3, 4) + vec4(G_Zero));
#line 23 1
        (l_v.yx = l_v.xy);
#line 23 1
        (l_v.w = float(9));
#line 23 1
        return all(equal(l_v, vec4(2, 1, 3, 9)));
      }
    case 12:
#line 24 1
      return (all(equal(not(bvec2(true, false)), bvec2(false, true))) && all(equal(((-vec2(1, (-2))) + vec2(G_Zero)), vec2((-1), 2))));
    case 13:
#line 25 1
      return (((uint((7 + G_IZero)) / 2u) == 3u) && ((uint((7 + G_IZero)) % 4u) == 3u));
    case 14:
#line 26 1
      {
#line 26 1
        int l_s = 0;
#line 26 1
        {
#line 26 1
          int l_k = 0;
          for (; (l_k < 10); (++l_k))
#line 26 1
            {
#line 26 1
              if ((l_k == 2))
#line 26 1
                continue;
#line 26 1
              if ((l_k == 6))
#line 26 1
                break;
#line 26 1
              (l_s += l_k);
            }
        }
#line 26 1
        return (l_s == (13 + G_IZero));
      }
    case 15:
#line 27 1
      {
#line 27 1
        int l_s = (0 + G_IZero);
        int l_k = 0;
#line 27 1
        while ((l_k < 4))
#line 27 1
          (l_s += (l_k++));
#line 27 1
        do
#line 27 1
          {
#line 27 1
            (l_s *= 2);
          }
        while ((l_s < 0));
#line 27 1
        return (l_s == 12);
      }
    default:
#line 28 1
      return true;
  }
}
#line 32 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 33 1
{
#line 34 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 32 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   operators.fx
1 of 1 files parse
