// technique function_statics pass 
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
float G_Count_n;
float G_CountOther_n;
int G_History_last[2];
float G_Accumulate_total;
float G_Accumulate_inner;
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
float F_Count()
#line 7 1
{
#line 7 1
#line 7 1
  (G_Count_n += 1.0);
#line 7 1
  return G_Count_n;
}
#line 8 1
float F_CountOther()
#line 8 1
{
#line 8 1
#line 8 1
  (G_CountOther_n += 2.0);
#line 8 1
  return G_CountOther_n;
}
#line 9 1
int F_History(int l_x)
#line 9 1
{
#line 9 1
#line 9 1
  int l_before = G_History_last[0];
#line 9 1
  (G_History_last[0] = G_History_last[1]);
#line 9 1
  (G_History_last[1] = l_x);
#line 9 1
  return l_before;
}
#line 10 1
float F_Weight(int l_k)
#line 10 1
{
#line 10 1
  float l_w[3] = float[3](0.25, 0.5, 0.25);
#line 10 1
  return l_w[l_k];
}
#line 11 1
float F_Accumulate(float l_x)
#line 12 1
{
#line 13 1
#line 14 1
  {
#line 14 1
    int l_i = 0;
    for (; (l_i < 3); (++l_i))
#line 14 1
      {
#line 14 1
#line 14 1
        (G_Accumulate_inner *= 2.0);
#line 14 1
        (G_Accumulate_total += (l_x * G_Accumulate_inner));
      }
  }
#line 15 1
  return G_Accumulate_total;
}
#line 18 1
bool F_Check(int l_i)
#line 19 1
{
#line 20 1
  switch (l_i) {
    case 0:
#line 22 1
      {
#line 22 1
        float l_a = F_Count();
#line 22 1
        float l_b = F_Count();
#line 22 1
        return ((l_a == 11.0) && (l_b == 12.0));
      }
    case 1:
#line 23 1
      {
#line 23 1
        float l_a = F_Count();
#line 23 1
        float l_b = F_CountOther();
#line 23 1
        float l_c = F_CountOther();
#line 23 1
        return (((l_a == 11.0) && (l_b == 2.0)) && (l_c == 4.0));
      }
    case 2:
#line 24 1
      {
#line 24 1
        F_History((5 + G_IZero));
#line 24 1
        F_History(6);
#line 24 1
        F_History(7);
#line 24 1
        return (F_History(8) == 6);
      }
    case 3:
#line 25 1
      return (((F_Weight((1 + G_IZero)) + F_Weight(0)) + F_Weight(2)) == 1.0);
    case 4:
#line 26 1
      {
#line 26 1
        float l_a = F_Accumulate((1.0 + G_Zero));
#line 26 1
        float l_b = F_Accumulate(1.0);
#line 26 1
        return ((l_a == 14.0) && (l_b == (14.0 + 112.0)));
      }
    case 5:
#line 27 1
      {
#line 27 1
        float l_a = F_Count();
#line 27 1
        {
#line 27 1
          int l_k = G_IZero;
          for (; (l_k < 4); (++l_k))
#line 27 1
            (l_a = F_Count());
        }
#line 27 1
        return (l_a == 15.0);
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
  G_Count_n = 10.0;
  G_CountOther_n = float(0);
  G_History_last = int[2](0, 0);
  G_Accumulate_total = 0.0;
  G_Accumulate_inner = 1.0;
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   function_statics.fx
1 of 1 files parse
