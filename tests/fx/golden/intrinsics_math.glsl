// technique intrinsics_math pass 
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
bool pfx_isfinite(float x) { return !(isnan(x) || isinf(x)); }
bvec2 pfx_isfinite(vec2 x) { return not(bvec2(ivec2(isnan(x)) | ivec2(isinf(x)))); }
bvec3 pfx_isfinite(vec3 x) { return not(bvec3(ivec3(isnan(x)) | ivec3(isinf(x)))); }
bvec4 pfx_isfinite(vec4 x) { return not(bvec4(ivec4(isnan(x)) | ivec4(isinf(x)))); }
int pfx_ftoi(float x) { return x >= 2147483648.0 ? 2147483647 : x > -2147483648.0 ? int(x) : x < 0.0 ? (-2147483647 - 1) : 0; }
ivec2 pfx_ftoi(vec2 x) { return mix(mix(mix(ivec2(0), ivec2(-2147483647 - 1), lessThan(x, vec2(0.0))), ivec2(x), greaterThan(x, vec2(-2147483648.0))), ivec2(2147483647), greaterThanEqual(x, vec2(2147483648.0))); }
ivec3 pfx_ftoi(vec3 x) { return mix(mix(mix(ivec3(0), ivec3(-2147483647 - 1), lessThan(x, vec3(0.0))), ivec3(x), greaterThan(x, vec3(-2147483648.0))), ivec3(2147483647), greaterThanEqual(x, vec3(2147483648.0))); }
ivec4 pfx_ftoi(vec4 x) { return mix(mix(mix(ivec4(0), ivec4(-2147483647 - 1), lessThan(x, vec4(0.0))), ivec4(x), greaterThan(x, vec4(-2147483648.0))), ivec4(2147483647), greaterThanEqual(x, vec4(2147483648.0))); }
float pfx_frexp(float x, out float e) { int i; float m = frexp(x, i); e = float(i); return m; }
vec2 pfx_frexp(vec2 x, out vec2 e) { ivec2 i; vec2 m = frexp(x, i); e = vec2(i); return m; }
vec3 pfx_frexp(vec3 x, out vec3 e) { ivec3 i; vec3 m = frexp(x, i); e = vec3(i); return m; }
vec4 pfx_frexp(vec4 x, out vec4 e) { ivec4 i; vec4 m = frexp(x, i); e = vec4(i); return m; }
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
#line 14 2
bool F_Close(float l_a, float l_b)
#line 14 2
{
#line 14 2
  return (abs((l_a - l_b)) <= (0.00100000005 * max(1.0, abs(l_b))));
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
#line 17 2
bool F_Near(vec3 l_a, vec3 l_b)
#line 17 2
{
#line 17 2
  return (F_Near(l_a.xy, l_b.xy) && F_Near(l_a.z, l_b.z));
}
#line 6 1
bool F_Check(int l_i)
#line 7 1
{
#line 8 1
  float l_s;
  float l_c;
  float l_e;
  float l_ip;
#line 9 1
  switch (l_i) {
    case 0:
#line 11 1
      return F_Near(pfx_fmod(((-5.5) + G_Zero), 2.0), (-1.5));
    case 1:
#line 12 1
      return F_Near(fract(((-1.25) + G_Zero)), 0.75);
    case 2:
#line 13 1
      return F_Near(mix(2.0, 4.0, (0.25 + G_Zero)), 2.5);
    case 3:
#line 14 1
      return ((clamp((1.5 + G_Zero), 0.0, 1.0) == 1.0) && (clamp(((-0.5) + G_Zero), 0.0, 1.0) == 0.0));
    case 4:
#line 15 1
      return F_Near(inversesqrt((4.0 + G_Zero)), 0.5);
    case 5:
#line 16 1
      return F_Near((1.0 / (4.0 + G_Zero)), 0.25);
    case 6:
#line 17 1
      return F_Near(atan((1.0 + G_Zero), (-1.0)), 2.3561945);
    case 7:
#line 18 1
      (l_s = sin((0.5 + G_Zero)), l_c = cos((0.5 + G_Zero)));
#line 18 1
      return (F_Near(l_s, 0.47942555) && F_Near(l_c, 0.87758255));
    case 8:
#line 19 1
      return (((step(0.5, (0.400000006 + G_Zero)) == 0.0) && (step(0.5, (0.600000024 + G_Zero)) == 1.0)) && (step(0.5, (0.5 + G_Zero)) == 1.0));
    case 9:
#line 20 1
      return F_Near(smoothstep(0.0, 2.0, (0.5 + G_Zero)), 0.15625);
    case 10:
#line 21 1
      return (((int(sign(((-3.0) + G_Zero))) == (-1)) && (int(sign(G_Zero)) == 0)) && (int(sign((2.5 + G_Zero))) == 1));
    case 11:
#line 22 1
      return (((roundEven((2.5 + G_Zero)) == 2.0) && (roundEven((3.5 + G_Zero)) == 4.0)) && (roundEven(((-2.5) + G_Zero)) == (-2.0)));
    case 12:
#line 23 1
      return (((trunc(((-1.70000005) + G_Zero)) == (-1.0)) && (floor(((-1.5) + G_Zero)) == (-2.0))) && (ceil(((-1.5) + G_Zero)) == (-1.0)));
    case 13:
#line 24 1
      return (((2.0 + G_Zero) * 3.0 + 4.0) == 10.0);
    case 14:
#line 25 1
      return (((1.5 + G_Zero) * exp2(3.0)) == 12.0);
    case 15:
#line 26 1
      {
#line 26 1
        float l_m = pfx_frexp((12.0 + G_Zero), l_e);
#line 26 1
        return ((l_m == 0.75) && (l_e == 4.0));
      }
    case 16:
#line 27 1
      {
#line 27 1
        float l_f = modf(((-2.75) + G_Zero), l_ip);
#line 27 1
        return ((l_f == (-0.75)) && (l_ip == (-2.0)));
      }
    case 17:
#line 28 1
      return ((F_Near((log2((1000.0 + G_Zero)) * 0.301029995663981), 3.0) && (exp2((3.0 + G_Zero)) == 8.0)) && F_Near(pow((2.0 + G_Zero), 10.0), 1024.0));
    case 18:
#line 29 1
      return ((F_Near(log(exp((1.0 + G_Zero))), 1.0) && F_Near(log2((8.0 + G_Zero)), 3.0)) && (sqrt((9.0 + G_Zero)) == 3.0));
    case 19:
#line 30 1
      return (dot(vec3(1, 2, 3), (vec3(4, 5, 6) + vec3(G_Zero))) == 32.0);
    case 20:
#line 31 1
      return all(equal(cross(vec3(1, 0, 0), (vec3(0, 1, 0) + vec3(G_Zero))), vec3(0, 0, 1)));
    case 21:
#line 32 1
      return (F_Near(length((vec2(3, 4) + vec2(G_Zero))), 5.0) && F_Near(distance(vec2(1, 1), (vec2(4, 5) + vec2(G_Zero))), 5.0));
    case 22:
#line 33 1
      return F_Near(normalize((vec2(0, 3) + vec2(G_Zero))), vec2(0, 1));
    case 23:
#line 34 1
      return F_Near(reflect((vec2(1, (-1)) + vec2(G_Zero)), vec2(0, 1)), vec2(1, 1));
    case 24:
#line 35 1
      return ((((abs(((-3) + G_IZero)) == 3) && (min(((-2) + G_IZero), 5) == (-2))) && (max((7u + uint(G_IZero)), 3u) == 7u)) && (clamp((12 + G_IZero), 0, 10) == 10));
    case 25:
#line 36 1
      return (F_Near(degrees((3.14159274 + G_Zero)), 180.0) && F_Near(radians((180.0 + G_Zero)), 3.14159274));
    case 26:
#line 37 1
      {
#line 37 1
        float l_x = (G_Zero / G_Zero);
#line 37 1
        float l_y = (1.0 / G_Zero);
#line 37 1
        return (((isnan(l_x) && isinf(l_y)) && (!pfx_isfinite(l_y))) && pfx_isfinite((1.0 + G_Zero)));
      }
    case 27:
#line 38 1
      return ((F_Close(sin((1.0 + G_Zero)), 0.841470957) && F_Close(cos((1.0 + G_Zero)), 0.540302336)) && F_Close(tan((0.5 + G_Zero)), 0.546302497));
    case 28:
#line 39 1
      return ((F_Close(asin((0.5 + G_Zero)), 0.52359879) && F_Close(acos((0.5 + G_Zero)), 1.04719758)) && F_Close(atan((1.0 + G_Zero)), 0.785398185));
    case 29:
#line 40 1
      return ((F_Close(sinh((1.0 + G_Zero)), 1.17520118) && F_Close(cosh((1.0 + G_Zero)), 1.54308069)) && F_Close(tanh((1.0 + G_Zero)), 0.761594176));
    case 30:
#line 41 1
      return (all(equal(max((vec2(1, 5) + vec2(G_Zero)), vec2(3, 2)), vec2(3, 5))) && all(equal(abs((vec2((-1), 2) + vec2(G_Zero))), vec2(1, 2))));
    case 31:
#line 42 1
      return (((any(bvec3((vec3(0, 0, 1) + vec3(G_Zero)))) && (!any(bvec2((vec2(0, 0) + vec2(G_Zero)))))) && all(bvec2((vec2(1, (-1)) + vec2(G_Zero))))) && (!all(bvec2((vec2(1, 0) + vec2(G_Zero))))));
    case 32:
#line 43 1
      return F_Near(mix(vec2(0, 10), (vec2(10, 20) + vec2(G_Zero)), vec2(0.5, 0.100000001)), vec2(5, 11));
    case 33:
#line 44 1
      return F_Near(pfx_fmod((vec2(5.5, (-7.0)) + vec2(G_Zero)), vec2(2.0, 3.0)), vec2(1.5, (-1.0)));
    case 34:
#line 45 1
      return F_Near(refract((vec2(0, (-1)) + vec2(G_Zero)), vec2(0, 1), (vec2(1.0)).x), vec2(0, (-1)));
    case 35:
#line 46 1
      return ((exp(G_Zero) == 1.0) && F_Near(exp((1.0 + G_Zero)), 2.71828175));
    case 36:
#line 47 1
      return (F_Near(fwidth(G_Zero), 0.0) && (dFdx(G_Zero) == 0.0));
    case 37:
#line 48 1
      return ((fract((2.0 + G_Zero)) == 0.0) && (fract((0.25 + G_Zero)) == 0.25));
    case 38:
#line 49 1
      return ((clamp(((-0.5) + G_Zero), 0.0, 1.0) == 0.0) && (min(((-0.0) + G_Zero), 0.5) <= 0.0));
    case 39:
#line 50 1
      return F_Near(clamp((vec3((-1), 0.5, 2) + vec3(G_Zero)), 0.0, 1.0), vec3(0, 0.5, 1));
    default:
#line 51 1
      return true;
  }
}
#line 55 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 56 1
{
#line 57 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 55 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   intrinsics_math.fx
1 of 1 files parse
