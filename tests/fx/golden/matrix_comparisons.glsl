// technique matrix_comparisons pass 
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
#line 7 1
bool F_Check(int l_i)
#line 8 1
{
  mat2 t_0;
  mat2 t_1;
  mat2 t_2;
  mat2 t_3;
  mat2 t_4;
  mat2 t_5;
  mat2 t_6;
  mat2 t_7;
  bvec2[2] t_8;
  mat2 t_9;
  mat2 t_10;
  bvec2[2] t_11;
  mat2 t_12;
  mat2 t_13;
  bvec2[2] t_14;
  mat2 t_15;
  mat2 t_16;
  bvec2[2] t_17;
  mat2 t_18;
  mat2 t_19;
  mat2 t_20;
  mat2 t_21;
  mat2x3 t_22;
  mat2x3 t_23;
  mat2x3 t_24;
  mat2x3 t_25;
  bvec3[2] t_26;
  mat2 t_27;
  mat2 t_28;
  bvec2[2] t_29;
  ivec2[2] t_30;
  ivec2[2] t_31;
  mat2 t_32;
  mat2 t_33;
  mat2 t_34;
  bvec2[2] t_35;
#line 9 1
  mat2 l_a = (mat2(1, 2, 3, 4) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 10 1
  mat2 l_b = (mat2(1, 5, 3, 0) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 11 1
  switch (l_i) {
    case 0:
#line 13 1
      {
#line 13 1
        bvec2[2] l_e = (t_0 = l_a, t_1 = l_b, bvec2[2](equal(t_0[0], t_1[0]), equal(t_0[1], t_1[1])));
#line 13 1
        return (((l_e[0][0] && (!l_e[0][1])) && l_e[1][0]) && (!l_e[1][1]));
      }
    case 1:
#line 14 1
      {
#line 14 1
        bvec2[2] l_n = (t_2 = l_a, t_3 = l_b, bvec2[2](notEqual(t_2[0], t_3[0]), notEqual(t_2[1], t_3[1])));
#line 14 1
        return ((((!l_n[0][0]) && l_n[0][1]) && (!l_n[1][0])) && l_n[1][1]);
      }
    case 2:
#line 15 1
      {
#line 15 1
        bvec2[2] l_l = (t_4 = l_a, t_5 = l_b, bvec2[2](lessThan(t_4[0], t_5[0]), lessThan(t_4[1], t_5[1])));
#line 15 1
        return ((((!l_l[0][0]) && l_l[0][1]) && (!l_l[1][0])) && (!l_l[1][1]));
      }
    case 3:
#line 16 1
      return ((((t_8 = (t_6 = l_a, t_7 = l_a, bvec2[2](equal(t_6[0], t_7[0]), equal(t_6[1], t_7[1]))), all(notEqual(t_8[0], bvec2(0))) && all(notEqual(t_8[1], bvec2(0)))) && (!(t_11 = (t_9 = l_a, t_10 = l_b, bvec2[2](equal(t_9[0], t_10[0]), equal(t_9[1], t_10[1]))), all(notEqual(t_11[0], bvec2(0))) && all(notEqual(t_11[1], bvec2(0)))))) && (t_14 = (t_12 = l_a, t_13 = l_b, bvec2[2](equal(t_12[0], t_13[0]), equal(t_12[1], t_13[1]))), any(notEqual(t_14[0], bvec2(0))) || any(notEqual(t_14[1], bvec2(0))))) && (!(t_17 = (t_15 = l_a, t_16 = l_a, bvec2[2](notEqual(t_15[0], t_16[0]), notEqual(t_15[1], t_16[1]))), any(notEqual(t_17[0], bvec2(0))) || any(notEqual(t_17[1], bvec2(0))))));
    case 4:
#line 17 1
      return ((((t_18 = l_a, all(notEqual(t_18[0], vec2(0))) && all(notEqual(t_18[1], vec2(0)))) && (!(t_19 = l_b, all(notEqual(t_19[0], vec2(0))) && all(notEqual(t_19[1], vec2(0)))))) && (t_20 = l_b, any(notEqual(t_20[0], vec2(0))) || any(notEqual(t_20[1], vec2(0))))) && (!(t_21 = matrixCompMult(l_a, mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero))), any(notEqual(t_21[0], vec2(0))) || any(notEqual(t_21[1], vec2(0))))));
    case 5:
#line 18 1
      {
#line 18 1
        mat2x3 l_c = (mat2x3(0, 0, 0, 0, 0, 1) + mat2x3(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero)));
#line 18 1
        return (((t_22 = l_c, any(notEqual(t_22[0], vec3(0))) || any(notEqual(t_22[1], vec3(0)))) && (!(t_23 = l_c, all(notEqual(t_23[0], vec3(0))) && all(notEqual(t_23[1], vec3(0)))))) && (t_26 = (t_24 = l_c, t_25 = mat2x3(float(0.0), float(0.0), float(0.0), float(0.0), float(0.0), float(0.0)), bvec3[2](greaterThanEqual(t_24[0], t_25[0]), greaterThanEqual(t_24[1], t_25[1]))), all(notEqual(t_26[0], bvec3(0))) && all(notEqual(t_26[1], bvec3(0)))));
      }
    case 6:
#line 19 1
      {
#line 19 1
        mat2 l_f = (t_29 = (t_27 = l_a, t_28 = l_b, bvec2[2](greaterThanEqual(t_27[0], t_28[0]), greaterThanEqual(t_27[1], t_28[1]))), mat2(vec2(t_29[0]), vec2(t_29[1])));
#line 19 1
        return (all(equal(l_f[0], vec2(1, 0))) && all(equal(l_f[1], vec2(1, 1))));
      }
    case 7:
#line 20 1
      {
#line 20 1
        ivec2[2] l_k = ivec2[2](ivec2(0, 0), ivec2(0, (-1)));
#line 20 1
        return ((t_30 = l_k, any(notEqual(t_30[0], ivec2(0))) || any(notEqual(t_30[1], ivec2(0)))) && (!(t_31 = l_k, all(notEqual(t_31[0], ivec2(0))) && all(notEqual(t_31[1], ivec2(0))))));
      }
    case 8:
#line 21 1
      {
#line 21 1
        mat2 l_nan = (mat2(0, 0, 0, 0) + mat2(float(sqrt(((-1.0) - G_Zero))), float(sqrt(((-1.0) - G_Zero))), float(sqrt(((-1.0) - G_Zero))), float(sqrt(((-1.0) - G_Zero)))));
#line 21 1
        return ((t_32 = l_nan, any(notEqual(t_32[0], vec2(0))) || any(notEqual(t_32[1], vec2(0)))) && (!(t_35 = (t_33 = l_nan, t_34 = l_nan, bvec2[2](equal(t_33[0], t_34[0]), equal(t_33[1], t_34[1]))), any(notEqual(t_35[0], bvec2(0))) || any(notEqual(t_35[1], bvec2(0))))));
      }
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
OK   matrix_comparisons.fx
1 of 1 files parse
