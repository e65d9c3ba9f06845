// The programs of the Gaussian modes (gaussian: one separable Gaussian; mgf: Kawase's multi-Gaussian), and the
// box bright pass they share with glare.
#include "bloom_shaders.hpp"
#include "shaders_common.hpp"

namespace pfx_bloom::shaders {

// Every texel of the frame is made safe and thresholded on its own, then a block x block square is
// averaged: the average keeps the light, and no texel is filtered before it is made safe. Block
// (x, y) starts at pixel (x, y) * block - pad: the buffer is rounded up and the frame centred on it
// (bloom_levels.hpp), so the blocks tile the frame exactly at any size, the padding reading black.
// With u_karis (mgf) every pixel is weighted by its Karis weight and the sum divided by the weights'.
std::string box_bright() {
  return std::string(kHeader) + kBrightCommon + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(location = 4) uniform int u_block;
layout(location = 5) uniform vec3 u_gain;
layout(location = 6) uniform float u_cap;
layout(location = 7) uniform ivec2 u_pad;
layout(location = 8) uniform int u_karis;

void main() {
  ivec2 size = textureSize(u_color, 0);
  ivec2 start = ivec2(gl_FragCoord.xy) * u_block - u_pad;
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int y = 0; y < u_block; ++y)
    for (int x = 0; x < u_block; ++x) {
      vec3 p = bright_part(safe_texel(u_color, start + ivec2(x, y), size));
      float w = u_karis != 0 ? karis_weight(p) : 1.0;
      sum += w * p;
      weights += w;
    }
  o_color = vec4(min(sum / weights * u_gain, vec3(u_cap)), 0.0);
}
)glsl";
}

// Taps one output texel apart along the direction. Reading a buffer of the same size every tap is
// a texel, fetched exactly (black outside): a bilinear read there would, through the sampler's
// rounding of coordinates, give the next texel a tiny weight and the kernel one texel more reach.
// Reading the finer buffer (u_finer) (mgf's next buffer, ceil(n / 2) texels), tap j reads at the corner
// between the source's texels 2j and 2j + 1, where the host's sampler (linear, clamp-to-border)
// makes it the average of the 2x2 texels it covers, black past the source's edge.
std::string blur() {
  return std::string(kHeader) + R"glsl(
layout(binding = 0) uniform sampler2D u_source;
layout(location = 4) uniform ivec2 u_direction;
layout(location = 5) uniform int u_half_taps;
layout(location = 6) uniform float u_weights[512];
layout(location = 520) uniform int u_finer;

void main() {
  ivec2 size = ivec2(u_out_size);
  vec3 sum;
  if (u_finer == 0) {
    // Along the direction only one coordinate moves: test it against its own side.
    ivec2 p = ivec2(gl_FragCoord.xy);
    int along = u_direction.x != 0 ? p.x : p.y, side = u_direction.x != 0 ? size.x : size.y;
    sum = u_weights[0] * texelFetch(u_source, p, 0).rgb;
    for (int k = 1; k <= u_half_taps; ++k) {
      vec3 pair = vec3(0.0);
      if (along + k < side) pair += texelFetch(u_source, p + k * u_direction, 0).rgb;
      if (along - k >= 0) pair += texelFetch(u_source, p - k * u_direction, 0).rgb;
      sum += u_weights[k] * pair;
    }
  } else {
    vec2 source = vec2(textureSize(u_source, 0));
    vec2 uv = 2.0 * gl_FragCoord.xy / source, step = 2.0 * vec2(u_direction) / source;
    sum = u_weights[0] * texture(u_source, uv).rgb;
    for (int k = 1; k <= u_half_taps; ++k)
      sum += u_weights[k] * (texture(u_source, uv + float(k) * step).rgb + texture(u_source, uv - float(k) * step).rgb);
  }
  o_color = vec4(sum, 0.0);
}
)glsl";
}

// The bloom buffer is upsampled with one bilinear tap (clamp-to-edge) at the pixel's place on the
// block grid.
std::string gaussian_composite() {
  return std::string(kHeader) + kFiniteFrame + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_bloom;
layout(location = 4) uniform float u_tone;
layout(location = 5) uniform int u_has_bloom;
layout(location = 6) uniform float u_block;
layout(location = 7) uniform vec2 u_pad;

void main() {
  vec4 c = finite_frame(texelFetch(u_color, ivec2(gl_FragCoord.xy), 0));
  vec3 sum = c.rgb * u_tone;
  if (u_has_bloom != 0)
    sum += texture(u_bloom, (gl_FragCoord.xy + u_pad) / (u_block * vec2(textureSize(u_bloom, 0)))).rgb;
  o_color = vec4(clamp(sum, vec3(-65504.0), vec3(65504.0)), c.a);
}
)glsl";
}

// Every blurred buffer upsampled with one bilinear tap (clamp-to-edge) at the pixel's place on its
// block grid (buffer i: blocks of 4 * 2^i pixels) and weighted.
std::string mgf_composite() {
  return std::string(kHeader) + kFiniteFrame + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_levels[15];
layout(location = 4) uniform int u_count;
layout(location = 5) uniform float u_weights[15];
layout(location = 20) uniform vec2 u_pad;

void main() {
  vec4 c = finite_frame(texelFetch(u_color, ivec2(gl_FragCoord.xy), 0));
  vec2 grid = gl_FragCoord.xy + u_pad;
  vec3 bloom = vec3(0.0);
  for (int i = 0; i < u_count; ++i)
    bloom += u_weights[i] * texture(u_levels[i], grid / (float(4 << i) * vec2(textureSize(u_levels[i], 0)))).rgb;
  o_color = vec4(min(c.rgb + bloom, vec3(65504.0)), c.a);
}
)glsl";
}

}  // namespace pfx_bloom::shaders
