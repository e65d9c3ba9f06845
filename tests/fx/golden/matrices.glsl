// technique matrices pass 
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
#line 6 1
bool F_Check(int l_i)
#line 7 1
{
#line 8 1
  mat2 l_a = (mat2(1, 2, 3, 4) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 9 1
  mat2 l_b = (mat2(5, 6, 7, 8) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 10 1
  mat3x2 l_n = (mat3x2(1, 2, 3, 4, 5, 6) + mat3x2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 11 1
  switch (l_i) {
    case 0:
#line 13 1
      return (((l_a[1][0] == 3.0) && (l_a[0][1] == 2.0)) && all(equal(l_a[1], vec2(3, 4))));
    case 1:
#line 14 1
      return all(equal((l_a * vec2(1, 2)), vec2(7, 10)));
    case 2:
#line 15 1
      return all(equal((vec2(1, 2) * l_a), vec2(5, 11)));
    case 3:
#line 16 1
      {
#line 16 1
        mat2 l_c = (l_b * l_a);
#line 16 1
        return ((((l_c[0][0] == 19.0) && (l_c[0][1] == 22.0)) && (l_c[1][0] == 43.0)) && (l_c[1][1] == 50.0));
      }
    case 4:
#line 17 1
      {
#line 17 1
        mat2 l_c = matrixCompMult(l_a, l_b);
#line 17 1
        return ((l_c[0][1] == 12.0) && (l_c[1][1] == 32.0));
      }
    case 5:
#line 18 1
      return ((((l_n[2][1] == 6.0) && (l_n[1][1] == 4.0)) && (l_n[2][1] == 6.0)) && (l_n[0][0] == 1.0));
    case 6:
#line 19 1
      return all(equal((l_n * vec3(1, 1, 1)), vec2(9, 12)));
    case 7:
#line 20 1
      {
#line 20 1
        mat2x3 l_t = transpose(l_n);
#line 20 1
        return ((l_t[1][2] == 6.0) && (l_t[0][1] == 3.0));
      }
    case 8:
#line 21 1
      return (determinant(l_a) == (-2.0));
    case 9:
#line 22 1
      {
#line 22 1
        mat4 l_m = (mat4(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16) + mat4(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 22 1
        mat3 l_s = mat3(l_m);
#line 22 1
        return ((l_s[2][2] == 11.0) && (l_s[1][0] == 5.0));
      }
    case 10:
#line 23 1
      {
#line 23 1
        mat2 l_s = mat2(float((2.0 + G_Zero)), float((2.0 + G_Zero)), float((2.0 + G_Zero)), float((2.0 + G_Zero)));
#line 23 1
        return ((l_s[0][1] == 2.0) && (l_s[1][0] == 2.0));
      }
    case 11:
#line 24 1
      {
#line 24 1
        vec4 l_v = vec4((l_a)[0], (l_a)[1]);
#line 24 1
        return all(equal(l_v, vec4(1, 2, 3, 4)));
      }
    default:
#line 25 1
      return true;
  }
}
#line 29 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 30 1
{
#line 31 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 29 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   matrices.fx
1 of 1 files parse
