// Counts frames three ways: feedback, FrameCount and history.
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
COMPAT_ATTRIBUTE vec2 Prev1TexCoord;
COMPAT_ATTRIBUTE vec2 PrevTexCoord;
COMPAT_ATTRIBUTE vec2 FeedbackTexCoord;
COMPAT_VARYING vec4 TEX0;
COMPAT_VARYING vec2 feedback_uv;
COMPAT_VARYING vec2 prev_uv;
COMPAT_VARYING vec2 prev1_uv;
uniform mat4 MVPMatrix;
void main() {
  gl_Position = MVPMatrix * VertexCoord;
  TEX0 = TexCoord;
  prev1_uv = Prev1TexCoord;
  prev_uv = PrevTexCoord;
  feedback_uv = FeedbackTexCoord;
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
COMPAT_VARYING vec2 feedback_uv;
COMPAT_VARYING vec2 prev_uv;
COMPAT_VARYING vec2 prev1_uv;
uniform sampler2D Texture;
uniform sampler2D FeedbackTexture;
uniform sampler2D PrevTexture;
uniform sampler2D Prev1Texture;
uniform int FrameCount;
// Red: its own output of the last frame (FeedbackTexture, feedback_pass = 0) plus 16 codes, so it
// counts the frames run; green: FrameCount; blue: the frame one and two frames back, mixed.
void main() {
  float frames = COMPAT_TEXTURE(FeedbackTexture, feedback_uv).r + 16.0 / 255.0;
  float count = mod(float(FrameCount), 256.0) / 255.0;
  float back = 0.5 * COMPAT_TEXTURE(PrevTexture, prev_uv).b + 0.5 * COMPAT_TEXTURE(Prev1Texture, prev1_uv).g;
  FragColor = vec4(frames, count, back, 1.0);
}
#endif
