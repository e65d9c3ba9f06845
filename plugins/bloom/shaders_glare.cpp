// The glare effect's programs (Kawase's star streaks); its bright pass is box_bright.
#include "bloom_shaders.hpp"
#include "shaders_common.hpp"

namespace pfx_bloom::shaders {

// Tap s reads the source b*s texels along the streak's direction (bilinear, clamp-to-border: black
// outside), so light at p + b*s*dir reaches p: the streak trails away from the light along -dir.
std::string streak() {
  return std::string(kHeader) + R"glsl(
layout(binding = 0) uniform sampler2D u_source;
layout(location = 4) uniform vec2 u_step;
layout(location = 5) uniform float u_weights[16];

void main() {
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 sum = vec3(0.0);
  for (int s = 0; s < 16; ++s) sum += u_weights[s] * texture(u_source, uv + float(s) * u_step).rgb;
  o_color = vec4(sum, 0.0);
}
)glsl";
}

// The streaks upsampled with one bilinear tap (clamp-to-edge) at the pixel's place on the block
// grid, times strength x tint, on the frame.
std::string glare_composite() {
  return std::string(kHeader) + kFiniteFrame + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_streaks;
layout(location = 4) uniform vec3 u_gain;
layout(location = 5) uniform float u_block;
layout(location = 6) uniform vec2 u_pad;

void main() {
  vec4 c = finite_frame(texelFetch(u_color, ivec2(gl_FragCoord.xy), 0));
  vec2 uv = (gl_FragCoord.xy + u_pad) / (u_block * vec2(textureSize(u_streaks, 0)));
  vec3 add = u_gain * texture(u_streaks, uv).rgb;
  o_color = vec4(min(c.rgb + add, vec3(65504.0)), c.a);
}
)glsl";
}

}  // namespace pfx_bloom::shaders
