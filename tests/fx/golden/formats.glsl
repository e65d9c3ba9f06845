// technique formats pass 
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
#line 9 1
vec4 F_WriteR8(vec4 l_position, vec2 l_texcoord)
#line 9 1
{
#line 9 1
  return vec4(0.200000003);
}
#line 9 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteR8(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 12 1
vec4 F_WriteR16(vec4 l_position, vec2 l_texcoord)
#line 12 1
{
#line 12 1
  return vec4(0.25);
}
#line 12 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteR16(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 15 1
vec4 F_WriteR16F(vec4 l_position, vec2 l_texcoord)
#line 15 1
{
#line 15 1
  return vec4((1.0 / 3.0));
}
#line 15 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteR16F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 18 1
vec4 F_WriteR32F(vec4 l_position, vec2 l_texcoord)
#line 18 1
{
#line 18 1
  return vec4((1.0 / 3.0));
}
#line 18 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteR32F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 21 1
vec4 F_WriteRG8(vec4 l_position, vec2 l_texcoord)
#line 21 1
{
#line 21 1
  return vec4(0.25, 0.75, 0, 0);
}
#line 21 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRG8(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 24 1
vec4 F_WriteRG16(vec4 l_position, vec2 l_texcoord)
#line 24 1
{
#line 24 1
  return vec4(0.25, 0.125, 0, 0);
}
#line 24 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRG16(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 27 1
vec4 F_WriteRG16F(vec4 l_position, vec2 l_texcoord)
#line 27 1
{
#line 27 1
  return vec4((1.0 / 3.0), (-2.5), 0, 0);
}
#line 27 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRG16F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 30 1
vec4 F_WriteRG32F(vec4 l_position, vec2 l_texcoord)
#line 30 1
{
#line 30 1
  return vec4((1.0 / 3.0), (-1e+10), 0, 0);
}
#line 30 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRG32F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 33 1
vec4 F_WriteRGBA8(vec4 l_position, vec2 l_texcoord)
#line 33 1
{
#line 33 1
  return vec4(0.200000003, 0.400000006, 0.600000024, 0.800000012);
}
#line 33 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRGBA8(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 36 1
vec4 F_WriteRGBA16(vec4 l_position, vec2 l_texcoord)
#line 36 1
{
#line 36 1
  return vec4(0.25, 0.125, 0.0625, 1.0);
}
#line 36 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRGBA16(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 39 1
vec4 F_WriteRGBA16F(vec4 l_position, vec2 l_texcoord)
#line 39 1
{
#line 39 1
  return vec4(65504.0, (-0.5), (1.0 / 3.0), 2.0);
}
#line 39 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRGBA16F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 42 1
vec4 F_WriteRGBA32F(vec4 l_position, vec2 l_texcoord)
#line 42 1
{
#line 42 1
  return vec4(1.00000002e+20, (-9.99999968e-21), (1.0 / 3.0), 7.0);
}
#line 42 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRGBA32F(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
#line 45 1
vec4 F_WriteRGB10A2(vec4 l_position, vec2 l_texcoord)
#line 45 1
{
#line 45 1
  return vec4(0.25, 0.125, 1.0, 0.699999988);
}
#line 45 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_WriteRGB10A2(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
layout(location = 0) out ivec4 pfx_target_0;
#line 48 1
ivec4 F_WriteR32I(vec4 l_position, vec2 l_texcoord)
#line 48 1
{
#line 48 1
  return ivec4((-123456));
}
#line 48 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  ivec4 r = F_WriteR32I(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
layout(location = 0) out uvec4 pfx_target_0;
#line 51 1
uvec4 F_WriteR32U(vec4 l_position, vec2 l_texcoord)
#line 51 1
{
#line 51 1
  return uvec4(4000000000u);
}
#line 51 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  uvec4 r = F_WriteR32U(p0, p1);
  pfx_target_0 = r;
}
// technique formats pass 
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
layout(binding = 0) uniform sampler2D G_SR8;
layout(binding = 1) uniform sampler2D G_SR16;
layout(binding = 2) uniform sampler2D G_SR16F;
layout(binding = 3) uniform sampler2D G_SR32F;
layout(binding = 4) uniform sampler2D G_SRG8;
layout(binding = 5) uniform sampler2D G_SRG16;
layout(binding = 6) uniform sampler2D G_SRG16F;
layout(binding = 7) uniform sampler2D G_SRG32F;
layout(binding = 8) uniform sampler2D G_SRGBA8;
layout(binding = 9) uniform sampler2D G_SRGBA16;
layout(binding = 10) uniform sampler2D G_SRGBA16F;
layout(binding = 11) uniform sampler2D G_SRGBA32F;
layout(binding = 12) uniform sampler2D G_SRGB10A2;
layout(binding = 13) uniform isampler2D G_SR32I;
layout(binding = 14) uniform usampler2D G_SR32U;
layout(binding = 0, std140) uniform pfx_uniforms {
  float G_Zero;
  int G_IZero;
};
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
uniform float pfx_target_height;
layout(location = 0) out vec4 pfx_target_0;
vec2 pfx_flip(vec2 c) { return vec2(c.x, 1.0 - c.y); }
vec3 pfx_flip(vec3 c) { return vec3(c.x, 1.0 - c.y, c.z); }
ivec2 pfx_flip_texel(ivec2 c, int h) { return ivec2(c.x, h - 1 - c.y); }
ivec3 pfx_flip_texel(ivec3 c, int h) { return ivec3(c.x, h - 1 - c.y, c.z); }
vec2 pfx_flip_offset(vec2 o) { return vec2(o.x, -o.y); }
vec3 pfx_flip_offset(vec3 o) { return vec3(o.x, -o.y, o.z); }
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
#line 18 2
bool F_Near(vec4 l_a, vec4 l_b)
#line 18 2
{
#line 18 2
  return (F_Near(l_a.xy, l_b.xy) && F_Near(l_a.zw, l_b.zw));
}
#line 53 1
bool F_Check(int l_i)
#line 54 1
{
#line 55 1
  vec4 l_v;
#line 56 1
  switch (l_i) {
    case 0:
#line 58 1
      (l_v = texelFetch(G_SR8, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR8, 0).y), 0));
#line 58 1
      return F_Near(l_v.x, (51.0 / 255.0));
    case 1:
#line 59 1
      (l_v = texelFetch(G_SR16, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR16, 0).y), 0));
#line 59 1
      return F_Near(l_v.x, (16384.0 / 65535.0));
    case 2:
#line 60 1
      (l_v = texelFetch(G_SR16F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR16F, 0).y), 0));
#line 60 1
      return (l_v.x == 0.333251953);
    case 3:
#line 61 1
      (l_v = texelFetch(G_SR32F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR32F, 0).y), 0));
#line 61 1
      return (l_v.x == (1.0 / 3.0));
    case 4:
#line 62 1
      (l_v = texelFetch(G_SRG8, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRG8, 0).y), 0));
#line 62 1
      return F_Near(l_v.xy, (vec2(64.0, 191.0) / vec2(255.0)));
    case 5:
#line 63 1
      (l_v = texelFetch(G_SRG16, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRG16, 0).y), 0));
#line 63 1
      return F_Near(l_v.xy, (vec2(16384.0, 8192.0) / vec2(65535.0)));
    case 6:
#line 64 1
      (l_v = texelFetch(G_SRG16F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRG16F, 0).y), 0));
#line 64 1
      return all(equal(l_v.xy, vec2(0.333251953, (-2.5))));
    case 7:
#line 65 1
      (l_v = texelFetch(G_SRG32F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRG32F, 0).y), 0));
#line 65 1
      return all(equal(l_v.xy, vec2((1.0 / 3.0), (-1e+10))));
    case 8:
#line 66 1
      (l_v = texelFetch(G_SRGBA8, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRGBA8, 0).y), 0));
#line 66 1
      return F_Near(l_v, (vec4(51, 102, 153, 204) / vec4(255.0)));
    case 9:
#line 67 1
      (l_v = texelFetch(G_SRGBA16, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRGBA16, 0).y), 0));
#line 67 1
      return F_Near(l_v, (vec4(16384.0, 8192.0, 4096.0, 65535.0) / vec4(65535.0)));
    case 10:
#line 68 1
      (l_v = texelFetch(G_SRGBA16F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRGBA16F, 0).y), 0));
#line 68 1
      return all(equal(l_v, vec4(65504.0, (-0.5), 0.333251953, 2.0)));
    case 11:
#line 69 1
      (l_v = texelFetch(G_SRGBA32F, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRGBA32F, 0).y), 0));
#line 69 1
      return all(equal(l_v, vec4(1.00000002e+20, (-9.99999968e-21), (1.0 / 3.0), 7.0)));
    case 12:
#line 70 1
      (l_v = texelFetch(G_SRGB10A2, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SRGB10A2, 0).y), 0));
#line 70 1
      return F_Near(l_v, vec4((256.0 / 1023.0), (128.0 / 1023.0), 1.0, (2.0 / 3.0)));
    case 13:
#line 71 1
      return ((texelFetch(G_SR32I, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR32I, 0).y), 0)).x == (-123456));
    case 14:
#line 72 1
      return ((texelFetch(G_SR32U, pfx_flip_texel(ivec2((ivec2(0, 0) + ivec2(G_IZero))), textureSize(G_SR32U, 0).y), 0)).x == 4000000000u);
    default:
#line 73 1
      return true;
  }
}
#line 77 1
vec4 F_Main(vec4 l_position, vec2 l_texcoord)
#line 78 1
{
#line 79 1
  return F_Verdict(F_Check(F_CheckIndex(l_position)));
}
#line 77 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, pfx_target_height - gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Main(p0, p1);
  pfx_target_0 = r;
}
OK   formats.fx
1 of 1 files parse
