// technique stencil_back_buffer pass 
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
#line 11 1
bool F_Right(vec4 l_position)
#line 11 1
{
#line 11 1
  return (l_position.x >= float((1920 / 2)));
}
#line 13 1
vec4 F_MarkLeft(vec4 l_position, vec2 l_texcoord)
#line 14 1
{
#line 15 1
  if (F_Right(l_position))
#line 15 1
    discard;
#line 16 1
  return vec4(1.0);
}
#line 13 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_MarkLeft(p0, p1);
  pfx_target_0 = r;
}
// technique stencil_back_buffer pass 
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
#line 11 2
vec4 F_Verdict(bool l_ok)
#line 11 2
{
#line 11 2
  return (l_ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0));
}
#line 11 1
bool F_Right(vec4 l_position)
#line 11 1
{
#line 11 1
  return (l_position.x >= float((1920 / 2)));
}
#line 18 1
vec4 F_GreenLeft(vec4 l_position, vec2 l_texcoord)
#line 18 1
{
#line 18 1
  return F_Verdict((!F_Right(l_position)));
}
#line 18 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_GreenLeft(p0, p1);
  pfx_target_0 = r;
}
// technique stencil_back_buffer pass 
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
#line 11 2
vec4 F_Verdict(bool l_ok)
#line 11 2
{
#line 11 2
  return (l_ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0));
}
#line 11 1
bool F_Right(vec4 l_position)
#line 11 1
{
#line 11 1
  return (l_position.x >= float((1920 / 2)));
}
#line 19 1
vec4 F_GreenRight(vec4 l_position, vec2 l_texcoord)
#line 19 1
{
#line 19 1
  return F_Verdict(F_Right(l_position));
}
#line 19 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_GreenRight(p0, p1);
  pfx_target_0 = r;
}
OK   stencil_back_buffer.fx
1 of 1 files parse
