// technique integer_matrices pass 
#version 450
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
  ivec2[2] G_Table;
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
  ivec2[2] G_Table;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
int pfx_imod(int x, int y) { return x - y * (x / y); }
ivec2 pfx_imod(ivec2 x, ivec2 y) { return x - y * (x / y); }
ivec3 pfx_imod(ivec3 x, ivec3 y) { return x - y * (x / y); }
ivec4 pfx_imod(ivec4 x, ivec4 y) { return x - y * (x / y); }
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
#line 11 1
void F_Halve(inout mat2 l_m)
#line 11 1
{
#line 11 1
  (l_m = matrixCompMult(l_m, mat2(float(0.5), float(0.5), float(0.5), float(0.5))));
}
#line 13 1
bool F_Check(int l_i)
#line 14 1
{
  ivec2[2] t_0;
  ivec2[2] t_1;
  ivec2[2] t_2;
  ivec2[2] t_3;
  ivec2[2] t_4;
  ivec2[2] t_5;
  ivec2[2] t_6;
  ivec2[2] t_7;
  ivec2[2] t_8;
  ivec2[2] t_9;
  ivec2[2] t_10;
  ivec2[2] t_11;
  ivec2[2] t_12;
  ivec2[2] t_13;
  ivec2[2] t_14;
  mat2 t_15;
  ivec2[2] t_16;
  ivec2 t_17;
  ivec2[2] t_18;
  bvec2[2] t_19;
  mat2 t_20;
  ivec2[2] t_21;
  mat2 t_22;
  ivec2[2] t_23;
  ivec2[2] t_24;
  ivec2[2] t_25;
  ivec2[2] t_26;
  bvec2[2] t_27;
  uvec2[2] t_28;
  uvec2[2] t_29;
#line 15 1
  ivec2[2] l_m = ivec2[2](ivec2((7 + G_IZero), 2), ivec2((-7), 3));
#line 16 1
  switch (l_i) {
    case 0:
#line 18 1
      {
#line 18 1
        ivec2[2] l_d = (t_0 = l_m, t_1 = ivec2[2](ivec2(2), ivec2(2)), ivec2[2]((t_0[0] / t_1[0]), (t_0[1] / t_1[1])));
#line 18 1
        return ((((l_d[0][0] == 3) && (l_d[0][1] == 1)) && (l_d[1][0] == (-3))) && (l_d[1][1] == 1));
      }
    case 1:
#line 19 1
      {
#line 19 1
        ivec2[2] l_r = (t_2 = l_m, t_3 = ivec2[2](ivec2(2), ivec2(2)), ivec2[2](pfx_imod(t_2[0], t_3[0]), pfx_imod(t_2[1], t_3[1])));
#line 19 1
        return ((((l_r[0][0] == 1) && (l_r[0][1] == 0)) && (l_r[1][0] == (-1))) && (l_r[1][1] == 1));
      }
    case 2:
#line 20 1
      {
#line 20 1
        ivec2[2] l_big = (t_4 = ivec2[2](ivec2((16777217 + G_IZero), 0), ivec2(0, 2147483647)), t_5 = ivec2[2](ivec2(1), ivec2(1)), ivec2[2]((t_4[0] + t_5[0]), (t_4[1] + t_5[1])));
#line 20 1
        return ((l_big[0][0] == 16777218) && (l_big[1][1] == ((-2147483647) - 1)));
      }
    case 3:
#line 21 1
      {
#line 21 1
        ivec2[2] l_b = (t_8 = (t_6 = l_m, t_7 = ivec2[2](ivec2(6), ivec2(6)), ivec2[2]((t_6[0] & t_7[0]), (t_6[1] & t_7[1]))), t_9 = ivec2[2](ivec2(8, 8), ivec2(0, 0)), ivec2[2]((t_8[0] | t_9[0]), (t_8[1] | t_9[1])));
#line 21 1
        return ((((l_b[0][0] == 14) && (l_b[0][1] == 10)) && (l_b[1][0] == 0)) && (l_b[1][1] == 2));
      }
    case 4:
#line 22 1
      {
#line 22 1
        ivec2[2] l_s = (t_12 = (t_10 = l_m, t_11 = ivec2[2](ivec2(2), ivec2(2)), ivec2[2]((t_10[0] << t_11[0]), (t_10[1] << t_11[1]))), t_13 = ivec2[2](ivec2(1), ivec2(1)), ivec2[2]((t_12[0] ^ t_13[0]), (t_12[1] ^ t_13[1])));
#line 22 1
        ivec2[2] l_n = (t_14 = l_m, ivec2[2]((~t_14[0]), (~t_14[1])));
#line 22 1
        return ((((l_s[0][0] == 29) && (l_s[1][0] == (-27))) && (l_n[0][0] == (-8))) && (l_n[1][0] == 6));
      }
    case 5:
#line 23 1
      {
#line 23 1
        ivec2[2] l_t = (t_15 = (mat2(1.5, (-1.5), 2.9000001, (-2.9000001)) + mat2(float(G_Zero), float(G_Zero), float(G_Zero), float(G_Zero))), ivec2[2](pfx_ftoi(t_15[0]), pfx_ftoi(t_15[1])));
#line 23 1
        return ((((l_t[0][0] == 1) && (l_t[0][1] == (-1))) && (l_t[1][0] == 2)) && (l_t[1][1] == (-2)));
      }
    case 6:
#line 24 1
      {
#line 24 1
        mat2 l_f = (t_16 = l_m, mat2(vec2(t_16[0]), vec2(t_16[1])));
#line 24 1
        (l_f = matrixCompMult(l_f, mat2(float(0.5), float(0.5), float(0.5), float(0.5))));
#line 24 1
        return ((l_f[0][0] == 3.5) && (l_f[1][0] == (-3.5)));
      }
    case 7:
#line 25 1
      {
#line 25 1
        ivec2[2] l_a = l_m;
#line 25 1
        (l_a[0][1] = 5);
#line 25 1
        (l_a[1] = ivec2(8, 9));
#line 25 1
        (l_a[0][0] += 3);
#line 25 1
        return (all(equal(l_a[0], ivec2(10, 5))) && all(equal(l_a[1], ivec2(8, 9))));
      }
    case 8:
#line 26 1
      {
#line 26 1
        ivec2[2] l_a = l_m;
#line 26 1
        (t_17 = ivec2((-1), (-2)), l_a[0][0] = t_17[0], l_a[1][1] = t_17[1], t_17);
#line 26 1
        return (((l_a[0][0] == (-1)) && (l_a[1][1] == (-2))) && (l_a[0][1] == 2));
      }
    case 9:
#line 27 1
      {
#line 27 1
        bvec2[2] l_b = (t_18 = ivec2[2](ivec2((0 + G_IZero), 3), ivec2(0, (-1))), bvec2[2](bvec2(t_18[0]), bvec2(t_18[1])));
#line 27 1
        bvec2[2] l_n = (t_19 = l_b, bvec2[2](not(t_19[0]), not(t_19[1])));
#line 27 1
        return ((((!l_b[0][0]) && l_b[0][1]) && l_n[0][0]) && (!l_n[1][1]));
      }
    case 10:
#line 28 1
      {
#line 28 1
        ivec2[2] l_a = l_m;
#line 28 1
        (t_20 = (t_21 = l_a, mat2(vec2(t_21[0]), vec2(t_21[1]))), F_Halve(t_20), (l_a = (t_22 = t_20, ivec2[2](pfx_ftoi(t_22[0]), pfx_ftoi(t_22[1])))));
#line 28 1
        return (((l_a[0][0] == 3) && (l_a[1][0] == (-3))) && (l_a[0][1] == 1));
      }
    case 11:
#line 29 1
      return ((((G_Table[0][0] == 1) && (G_Table[0][1] == (-2))) && (G_Table[1][0] == 3)) && ((G_Table[1][1] / 3) == 13333333));
    case 12:
#line 30 1
      {
#line 30 1
        ivec2[3] l_r = ivec2[3](ivec2(((ivec2(1, 2) + ivec2(G_IZero)))[0], ((ivec2(1, 2) + ivec2(G_IZero)))[1]), ivec2((ivec2(3, 4))[0], (ivec2(3, 4))[1]), ivec2((ivec2(5, 6))[0], (ivec2(5, 6))[1]));
#line 30 1
        return (((l_r[2][1] == 6) && (l_r[1][0] == 3)) && all(equal(l_r[2], ivec2(5, 6))));
      }
    case 13:
#line 31 1
      {
#line 31 1
        ivec4 l_v = ivec4(ivec4((l_m)[0], (l_m)[1]));
#line 31 1
        return all(equal(l_v, ivec4(7, 2, (-7), 3)));
      }
    case 14:
#line 32 1
      {
#line 32 1
        bvec2[2] l_e = (t_23 = l_m, t_24 = ivec2[2](ivec2(7, 0), ivec2((-7), 0)), bvec2[2](equal(t_23[0], t_24[0]), equal(t_23[1], t_24[1])));
#line 32 1
        return (((l_e[0][0] && (!l_e[0][1])) && l_e[1][0]) && (t_27 = (t_25 = l_m, t_26 = l_m, bvec2[2](equal(t_25[0], t_26[0]), equal(t_25[1], t_26[1]))), all(notEqual(t_27[0], bvec2(0))) && all(notEqual(t_27[1], bvec2(0)))));
      }
    case 15:
#line 33 1
      {
#line 33 1
        uvec2[2] l_u = (t_28 = uvec2[2](uvec2((0u + uint(G_IZero)), 5u), uvec2(7u, 9u)), t_29 = uvec2[2](uvec2(1u), uvec2(1u)), uvec2[2]((t_28[0] - t_29[0]), (t_28[1] - t_29[1])));
#line 33 1
        return ((l_u[0][0] == 4294967295u) && ((l_u[0][1] / 2u) == 2u));
      }
    default:
#line 34 1
      return true;
  }
}
#line 38 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 39 1
{
#line 40 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 38 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   integer_matrices.fx
1 of 1 files parse
