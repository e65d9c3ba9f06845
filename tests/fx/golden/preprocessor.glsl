// technique preprocessor pass 
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
vec2 G_ReShade_ns_PixelSize;
int G_LineHere;
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
#line 40 1
bool F_Check(int l_i)
#line 41 1
{
#line 42 1
  int l_myvalue = (7 + G_IZero);
#line 43 1
  switch (l_i) {
    case 0:
#line 45 1
      return (((((3 + G_IZero) * (3 + G_IZero)) == 9) && ((((1 + 2) + 3) + G_IZero) == 6)) && ((((1 + 2) + 3) + G_IZero) == 6));
    case 1:
#line 46 1
      return ((l_myvalue == 7) && (((2 * 2) + G_IZero) == 4));
    case 2:
#line 47 1
      return ((1 == (1 + G_IZero)) && (1 == 1));
    case 3:
#line 48 1
      return (G_LineHere == 38);
    case 4:
#line 49 1
      return ((1920 == 64) && (1080 == (2 + G_IZero)));
    case 5:
#line 50 1
      return (F_Near(((1.0 / float(1920)) + G_Zero), (1.0 / 64.0)) && F_Near(((1.0 / float(1080)) + G_Zero), 0.5));
    case 6:
#line 51 1
      return (((8 == 8) && (60300 >= 50000)) && (83200 == (83200 + G_IZero)));
    case 7:
#line 52 1
      return (F_Near((G_ReShade_ns_PixelSize + vec2(G_Zero)), vec2((1.0 / 64.0), 0.5)) && F_Near(((float(1920) * (1.0 / float(1080))) + G_Zero), 32.0));
    case 8:
#line 56 1
      return false;
    default:
#line 58 1
      return true;
  }
}
#line 62 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 63 1
{
#line 64 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 62 1
void main() {
  G_ReShade_ns_PixelSize = vec2((1.0 / float(1920)), (1.0 / float(1080)));
  G_LineHere = 38;
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   preprocessor.fx
1 of 1 files parse
