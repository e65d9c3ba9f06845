// technique matrix_swizzle_stores pass 
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
#line 8 1
bool F_Check(int l_i)
#line 9 1
{
  vec2 t_0;
  vec2 t_1;
  vec2 t_2;
  vec2 t_3;
  vec3 t_4;
  vec2 t_5;
  vec2 t_6;
  vec2 t_7;
  vec2 t_8;
#line 10 1
  mat2 l_m = (mat2(1, 2, 3, 4) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 11 1
  mat3 l_z = mat3(float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)), float((0.0 + G_Zero)));
#line 12 1
  switch (l_i) {
    case 0:
#line 14 1
      {
#line 14 1
        mat3 l_a = l_z;
#line 14 1
        (t_0 = (vec2(5, 6) + vec2(G_Zero)), l_a[0][0] = t_0[0], l_a[1][1] = t_0[1], t_0);
#line 14 1
        return ((((l_a[0][0] == 5.0) && (l_a[1][1] == 6.0)) && (l_a[2][2] == 0.0)) && (l_a[0][1] == 0.0));
      }
    case 1:
#line 15 1
      {
#line 15 1
        mat2 l_a = l_m;
#line 15 1
        (t_1 = (vec2(l_a[0][1], l_a[1][0]) + vec2(10, 20)), l_a[0][1] = t_1[0], l_a[1][0] = t_1[1], t_1);
#line 15 1
        return ((((l_a[0][1] == 12.0) && (l_a[1][0] == 23.0)) && (l_a[0][0] == 1.0)) && (l_a[1][1] == 4.0));
      }
    case 2:
#line 16 1
      {
#line 16 1
        mat2 l_a = l_m;
#line 16 1
        (t_2 = vec2(l_a[1][0], l_a[1][1]), l_a[0][0] = t_2[0], l_a[0][1] = t_2[1], t_2);
#line 16 1
        return (all(equal(l_a[0], vec2(3, 4))) && all(equal(l_a[1], vec2(3, 4))));
      }
    case 3:
#line 17 1
      {
#line 17 1
        mat2 l_a = l_m;
#line 17 1
        (t_3 = vec2(l_a[0][1], l_a[0][0]), l_a[0][0] = t_3[0], l_a[0][1] = t_3[1], t_3);
#line 17 1
        return all(equal(l_a[0], vec2(2, 1)));
      }
    case 4:
#line 18 1
      {
#line 18 1
        mat3 l_a = l_z;
#line 18 1
        (t_4 = (vec3(1, 2, 3) + vec3(G_Zero)), l_a[0][0] = t_4[0], l_a[1][1] = t_4[1], l_a[2][2] = t_4[2], t_4);
#line 18 1
        return ((((l_a[0][0] == 1.0) && (l_a[1][1] == 2.0)) && (l_a[2][2] == 3.0)) && (l_a[2][0] == 0.0));
      }
    case 5:
#line 19 1
      {
#line 19 1
        mat2 l_a = l_m;
#line 19 1
        vec2 l_v = (t_5 = (vec2(8, 9) + vec2(G_Zero)), l_a[1][0] = t_5[0], l_a[1][1] = t_5[1], t_5);
#line 19 1
        return (all(equal(l_v, vec2(8, 9))) && (l_a[1][1] == 9.0));
      }
    case 6:
#line 20 1
      {
#line 20 1
        mat2 l_a = l_m;
#line 20 1
        (t_6 = (vec2(l_a[0][0], l_a[1][1]) * vec2(3.0)), l_a[0][0] = t_6[0], l_a[1][1] = t_6[1], t_6);
#line 20 1
        return (((l_a[0][0] == 3.0) && (l_a[1][1] == 12.0)) && (l_a[0][1] == 2.0));
      }
    case 7:
#line 21 1
      {
#line 21 1
        mat2 l_a = l_m;
#line 21 1
        (t_7 = vec2((7.0 + G_Zero)), l_a[1][0] = t_7[0], l_a[0][1] = t_7[1], t_7);
#line 21 1
        return (((l_a[1][0] == 7.0) && (l_a[0][1] == 7.0)) && (l_a[0][0] == 1.0));
      }
    case 8:
#line 22 1
      {
#line 22 1
        mat2 l_a = l_m;
#line 22 1
        (t_8 = (vec2(5, 6) + vec2(G_Zero)), l_a[1][1] = t_8[0], l_a[0][0] = t_8[1], t_8);
#line 22 1
        return ((l_a[1][1] == 5.0) && (l_a[0][0] == 6.0));
      }
    default:
#line 23 1
      return true;
  }
}
#line 27 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 28 1
{
#line 29 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 27 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   matrix_swizzle_stores.fx
1 of 1 files parse
