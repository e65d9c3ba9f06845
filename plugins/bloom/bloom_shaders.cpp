#include "bloom_shaders.hpp"

namespace pfx_bloom::shaders {

// The bright pass cannot let the hardware filter the frame: one NaN texel poisons every bilinear
// tap that touches it, even with weight 0 (NaN * 0 = NaN), and from there the whole pyramid. So it
// fetches texels itself, makes each one safe (NaN -> 0, negative -> 0, at most the firefly clamp,
// which also catches +Inf), and only then does the seed's five bilinear taps in arithmetic, with
// clamp-to-border (black outside the frame). NaN is tested on the bits: a compiler may assume
// floats are never NaN and fold isnan() away.
const char* const kBright = R"glsl(#version 450 core
layout(binding = 0) uniform sampler2D u_color;
layout(location = 0) uniform vec2 u_out_size;
layout(location = 1) uniform vec2 u_curve;
layout(location = 2) uniform int u_measure;
layout(location = 3) uniform float u_clamp;
layout(location = 4) uniform vec3 u_gain;
layout(location = 5) uniform float u_cap;
layout(location = 0) out vec4 o_color;

ivec2 g_size;

vec3 safe_texel(ivec2 p) {
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, g_size))) return vec3(0.0);
  vec3 c = texelFetch(u_color, p, 0).rgb;
  bvec3 nan = greaterThan(floatBitsToUint(c) & uvec3(0x7fffffffu), uvec3(0x7f800000u));
  c = mix(c, vec3(0.0), nan);
  return clamp(c, vec3(0.0), vec3(u_clamp));
}

vec3 bright_part(vec3 c) {
  float b = u_measure == 1 ? dot(c, vec3(0.2126, 0.7152, 0.0722)) : max(c.r, max(c.g, c.b));
  float t = u_curve.x, k = u_curve.y;
  float part = max(b - t, 0.0);
  if (k > 0.0) {
    float s = clamp(b - t + k, 0.0, 2.0 * k);
    part = max(part, s * s / (4.0 * k));
  }
  return c * (part / max(b, 1e-5));
}

// The five taps (the centre, and one texel off along each diagonal) fall at the same fraction
// between texels, so together they read the 4x4 texels around the centre: fetched once, then
// mixed as GL_LINEAR would (texel centres at +0.5).
vec3 tap(vec3 t[4][4], int x, int y, vec2 f) {
  return mix(mix(t[y][x], t[y][x + 1], f.x), mix(t[y + 1][x], t[y + 1][x + 1], f.x), f.y);
}

void main() {
  g_size = textureSize(u_color, 0);
  vec2 q = gl_FragCoord.xy / u_out_size * vec2(g_size) - 0.5;
  vec2 base = floor(q);
  vec2 f = q - base;
  ivec2 i = ivec2(base) - 1;
  vec3 t[4][4];
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) t[y][x] = safe_texel(i + ivec2(x, y));
  vec3 sum = 4.0 * bright_part(tap(t, 1, 1, f));
  sum += bright_part(tap(t, 0, 2, f));
  sum += bright_part(tap(t, 2, 2, f));
  sum += bright_part(tap(t, 0, 0, f));
  sum += bright_part(tap(t, 2, 0, f));
  o_color = vec4(min(sum * (1.0 / 8.0) * u_gain, vec3(u_cap)), 0.0);
}
)glsl";

// The sampler is the host's: linear, clamp-to-border (black) while going down.
const char* const kDown = R"glsl(#version 450 core
layout(binding = 0) uniform sampler2D u_source;
layout(location = 0) uniform vec2 u_out_size;
layout(location = 0) out vec4 o_color;

void main() {
  const float offsets[4] = float[4](-2.75, -0.92, 0.92, 2.75);
  const float weights[4] = float[4](0.1087, 0.3913, 0.3913, 0.1087);
  vec2 texel = 1.0 / vec2(textureSize(u_source, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 sum = vec3(0.0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      sum += texture(u_source, uv + vec2(offsets[x], offsets[y]) * texel).rgb * (weights[x] * weights[y]);
  o_color = vec4(sum, 0.0);
}
)glsl";

// The sampler is the host's: linear, clamp-to-edge while going up. The host blends it (ONE, ONE)
// into the level below.
const char* const kUp = R"glsl(#version 450 core
layout(binding = 0) uniform sampler2D u_source;
layout(location = 0) uniform vec2 u_out_size;
layout(location = 0) out vec4 o_color;

void main() {
  vec2 h = 0.5 / vec2(textureSize(u_source, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 sum = texture(u_source, uv + vec2(-h.x, h.y)).rgb + texture(u_source, uv + vec2(h.x, h.y)).rgb +
             texture(u_source, uv + vec2(h.x, -h.y)).rgb + texture(u_source, uv + vec2(-h.x, -h.y)).rgb;
  o_color = vec4(sum * 0.25, 0.0);
}
)glsl";

// The last upsample, added to the frame here rather than by blending, so the frame's own bad values
// can be made finite too: NaN -> 0 and +-Inf -> +-65504 in every channel, alpha included, and the
// sum stays at most 65504.
const char* const kComposite = R"glsl(#version 450 core
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_level0;
layout(location = 0) uniform vec2 u_out_size;
layout(location = 0) out vec4 o_color;

void main() {
  vec4 c = texelFetch(u_color, ivec2(gl_FragCoord.xy), 0);
  bvec4 nan = greaterThan(floatBitsToUint(c) & uvec4(0x7fffffffu), uvec4(0x7f800000u));
  c = clamp(mix(c, vec4(0.0), nan), vec4(-65504.0), vec4(65504.0));
  vec2 h = 0.5 / vec2(textureSize(u_level0, 0));
  vec2 uv = gl_FragCoord.xy / u_out_size;
  vec3 bloom = texture(u_level0, uv + vec2(-h.x, h.y)).rgb + texture(u_level0, uv + vec2(h.x, h.y)).rgb +
               texture(u_level0, uv + vec2(h.x, -h.y)).rgb + texture(u_level0, uv + vec2(-h.x, -h.y)).rgb;
  o_color = vec4(min(c.rgb + bloom * 0.25, vec3(65504.0)), c.a);
}
)glsl";

}  // namespace pfx_bloom::shaders
