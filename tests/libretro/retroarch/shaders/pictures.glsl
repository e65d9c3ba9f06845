// Reads the pictures before it by each name the GLSL form gives them.
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
COMPAT_ATTRIBUTE vec2 OrigTexCoord;
COMPAT_ATTRIBUTE vec2 PassPrev1TexCoord;
COMPAT_ATTRIBUTE vec2 firstTexCoord;
COMPAT_VARYING vec4 TEX0;
COMPAT_VARYING vec2 orig_uv;
COMPAT_VARYING vec2 prev1_uv;
COMPAT_VARYING vec2 first_uv;
uniform mat4 MVPMatrix;
void main() {
  gl_Position = MVPMatrix * VertexCoord;
  TEX0 = TexCoord;
  orig_uv = OrigTexCoord;
  prev1_uv = PassPrev1TexCoord;
  first_uv = firstTexCoord;
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
COMPAT_VARYING vec2 orig_uv;
COMPAT_VARYING vec2 prev1_uv;
COMPAT_VARYING vec2 first_uv;
uniform sampler2D Texture;
uniform sampler2D OrigTexture;
uniform sampler2D PassPrev1Texture;
uniform sampler2D firstTexture;
uniform vec2 OrigInputSize;
uniform vec2 Pass1InputSize;
uniform vec2 OutputSize;
// Four bands across: the frame (Orig), the first pass's output by its alias, the second pass's by
// PassPrev1 with a quarter of the input (Texture, the same picture), and the sizes as fractions of
// 1024. One name per picture: RetroArch binds a picture to the first of its names a shader
// declares (Orig before PassPrevN; PassN, then PassPrevN, then the alias) and leaves the others
// unset.
void main() {
  float x = gl_FragCoord.x / OutputSize.x;
  vec3 c;
  if (x < 0.25)
    c = COMPAT_TEXTURE(OrigTexture, orig_uv).rgb;
  else if (x < 0.5)
    c = COMPAT_TEXTURE(firstTexture, first_uv).gbr;
  else if (x < 0.75)
    c = COMPAT_TEXTURE(PassPrev1Texture, prev1_uv).rgb + 0.25 * COMPAT_TEXTURE(Texture, TEX0.xy).rgb;
  else
    c = vec3(OrigInputSize.x, OrigInputSize.y, Pass1InputSize.x) / 1024.0;
  FragColor = vec4(c, 1.0);
}
#endif
