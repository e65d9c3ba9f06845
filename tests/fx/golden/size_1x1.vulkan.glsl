// technique size_1x1 pass 
#version 450
layout(location = 0) out vec4 pfx_v_TEXCOORD0;
#line 63 2
void F_PostProcessVS(uint l_id, out vec4 l_position, out vec2 l_texcoord)
#line 64 2
{
#line 65 2
  (l_texcoord = vec2(((l_id == uint(2)) ? 2.0 : 0.0), ((l_id == uint(1)) ? 2.0 : 0.0)));
#line 66 2
  (l_position = vec4(((l_texcoord * vec2(2.0, (-2.0))) + vec2((-1.0), 1.0)), 0.0, 1.0));
}
#line 63 2
void main() {
  pfx_v_TEXCOORD0 = vec4(0);
  uint p0;
  vec4 p1;
  vec2 p2;
  p0 = uint(gl_VertexIndex);
  F_PostProcessVS(p0, p1, p2);
  gl_Position = p1;
  gl_Position.y = -gl_Position.y;
  pfx_v_TEXCOORD0 = vec4(p2, 0, 1);
}
#version 450
layout(set = 0, binding = 1) uniform sampler2D G_ReShade_ns_BackBuffer;
layout(location = 0) in vec4 pfx_v_TEXCOORD0;
layout(location = 0) out vec4 pfx_target_0;
vec2 pfx_flip(vec2 c) { return c; }
vec3 pfx_flip(vec3 c) { return c; }
ivec2 pfx_flip_texel(ivec2 c, int h) { return c; }
ivec3 pfx_flip_texel(ivec3 c, int h) { return c; }
vec2 pfx_flip_offset(vec2 o) { return o; }
vec3 pfx_flip_offset(vec3 o) { return o; }
#line 5 1
vec4 F_Copy(vec4 l_position, vec2 l_texcoord)
#line 6 1
{
#line 7 1
  return (((1920 == 1) && (1080 == 1)) ? texture(G_ReShade_ns_BackBuffer, pfx_flip(vec2((l_texcoord + vec2((1.0 / float(1920)), (1.0 / float(1080))))))) : vec4(0.0));
}
#line 5 1
void main() {
  vec4 p0;
  vec2 p1;
  p0 = vec4(gl_FragCoord.x, gl_FragCoord.y, gl_FragCoord.z, 1.0 / gl_FragCoord.w);
  p1 = vec2(pfx_v_TEXCOORD0);
  vec4 r = F_Copy(p0, p1);
  pfx_target_0 = r;
}
OK   size_1x1.fx
1 of 1 files parse
