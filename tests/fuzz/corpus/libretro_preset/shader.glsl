// Each channel c as c * gain + lift: a parameter the preset sets and one left at its default.
#pragma parameter gain "Gain" 0.5 0.0 2.0 0.05
#pragma parameter lift "Lift" 0.125 0.0 1.0 0.025
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
#ifdef PARAMETER_UNIFORM
uniform float gain;
uniform float lift;
#else
#define gain 0.5
#define lift 0.125
#endif
void main() {
  FragColor = vec4(COMPAT_TEXTURE(Texture, TEX0.xy).rgb * gain + lift, 1.0);
}
#endif
