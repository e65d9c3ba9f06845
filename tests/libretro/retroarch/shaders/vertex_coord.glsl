// VertexCoord's y in green, and the input's green moved to red: run twice, the output shows
// pass 0's VertexCoord (a pass into a texture) in red and pass 1's (the pass onto the screen) in
// green. RetroArch's gl driver gives the two passes VertexCoord turned over from each other, and
// cocktail-cabinet makes its texture coordinates from VertexCoord.
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
COMPAT_VARYING vec2 position;
uniform mat4 MVPMatrix;
void main() {
  gl_Position = MVPMatrix * VertexCoord;
  TEX0 = TexCoord;
  position = VertexCoord.xy;
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
COMPAT_VARYING vec2 position;
uniform sampler2D Texture;
void main() {
  vec3 input_colour = COMPAT_TEXTURE(Texture, TEX0.xy).rgb;
  FragColor = vec4(input_colour.g, position.y, input_colour.b, 1.0);
}
#endif
