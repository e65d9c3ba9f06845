// Shows the pass before and its own FrameCount.
#if defined(VERTEX)
#if __VERSION__ >= 130
#define COMPAT_VARYING out
#define COMPAT_ATTRIBUTE in
#else
#define COMPAT_VARYING varying
#define COMPAT_ATTRIBUTE attribute
#endif
COMPAT_ATTRIBUTE vec4 VertexCoord;
COMPAT_ATTRIBUTE vec4 TexCoord;
COMPAT_VARYING vec4 TEX0;
uniform mat4 MVPMatrix;
void main() {
  gl_Position = MVPMatrix * VertexCoord;
  TEX0 = TexCoord;
}
#elif defined(FRAGMENT)
#if __VERSION__ >= 130
#define COMPAT_VARYING in
#define COMPAT_TEXTURE texture
out vec4 FragColor;
#else
#define COMPAT_VARYING varying
#define FragColor gl_FragColor
#define COMPAT_TEXTURE texture2D
#endif
COMPAT_VARYING vec4 TEX0;
uniform sampler2D Texture;
uniform int FrameCount;
// The pass before, with blue in the right half replaced by this pass's FrameCount (the preset
// wraps it with frame_count_mod1).
void main() {
  vec3 c = COMPAT_TEXTURE(Texture, TEX0.xy).rgb;
  if (gl_FragCoord.x > 320.0) c.b = float(FrameCount) / 255.0;
  FragColor = vec4(c, 1.0);
}
#endif
