// The GLSL every bloom and glare program shares: the version line, the output-size uniform, and the
// bright pass's treatment of bad values and its threshold curve. Kept in one place so the modes
// cannot drift apart, and mirrored in double precision by reference/model_common.cpp.
#include "shaders_common.hpp"

namespace pfx_bloom::shaders {

// u_nonfinite (Nonfinite, bloom_params.hpp) is read by the programs that read the frame; it is
// declared for all so that no program can declare it twice.
const char* const kHeader = R"glsl(#version 450 core
layout(location = 0) uniform vec2 u_out_size;
layout(location = 600) uniform int u_nonfinite;
layout(location = 0) out vec4 o_color;

// NaN or +-Inf: every exponent bit set.
bvec3 not_finite(vec3 c) { return greaterThanEqual(floatBitsToUint(c) & uvec3(0x7fffffffu), uvec3(0x7f800000u)); }
)glsl";

// NaN is tested on the bits: a compiler may assume floats are never NaN and fold isnan() away.
// Measure 0: max(R,G,B) with the pyramid's ratio; 1: Rec. 709 luminance with the same ratio;
// 2: every channel thresholded on its own (the separable Gaussian bloom's max(c - threshold, 0)).
const char* const kBrightCommon = R"glsl(
layout(location = 1) uniform vec2 u_curve;
layout(location = 2) uniform int u_measure;
layout(location = 3) uniform float u_clamp;

// nonfinite zero: a pixel with NaN or +-Inf in any channel is black. clamp: NaN -> 0 per channel
// (+Inf is caught by the clamp below). Then negative -> 0, at most the firefly clamp.
vec3 safe_color(vec3 c) {
  if (u_nonfinite == 0 && any(not_finite(c))) return vec3(0.0);
  bvec3 nan = greaterThan(floatBitsToUint(c) & uvec3(0x7fffffffu), uvec3(0x7f800000u));
  return clamp(mix(c, vec3(0.0), nan), vec3(0.0), vec3(u_clamp));
}

// Karis's weight of a tap's bright part: 1 / (1 + Rec. 709 luma).
float karis_weight(vec3 p) { return 1.0 / (1.0 + dot(p, vec3(0.2126, 0.7152, 0.0722))); }

// A texel of the frame made safe; black outside it (clamp-to-border).
vec3 safe_texel(sampler2D s, ivec2 p, ivec2 size) {
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return vec3(0.0);
  return safe_color(texelFetch(s, p, 0).rgb);
}

// The threshold curve: max(b - t, 0), or with a knee k the quadratic s^2 / 4k, s = clamp(b - t + k, 0, 2k).
float soft_part(float b) {
  float t = u_curve.x, k = u_curve.y;
  float part = max(b - t, 0.0);
  if (k > 0.0) {
    float s = clamp(b - t + k, 0.0, 2.0 * k);
    part = max(part, s * s / (4.0 * k));
  }
  return part;
}

vec3 bright_part(vec3 c) {
  if (u_measure == 2) return vec3(soft_part(c.r), soft_part(c.g), soft_part(c.b));
  float b = u_measure == 1 ? dot(c, vec3(0.2126, 0.7152, 0.0722)) : max(c.r, max(c.g, c.b));
  return c * (soft_part(b) / max(b, 1e-5));
}
)glsl";

// The frame as the composite passes it on. nonfinite zero: a pixel with NaN or +-Inf in R, G or B
// is black, and a non-finite alpha 0 (alone: alpha is not light). clamp: NaN -> 0 and +-Inf ->
// +-65504 in every channel, alpha included. Both: at most +-65504.
const char* const kFiniteFrame = R"glsl(
vec4 finite_frame(vec4 c) {
  if (u_nonfinite == 0) {
    if (any(not_finite(c.rgb))) c.rgb = vec3(0.0);
    if ((floatBitsToUint(c.a) & 0x7fffffffu) >= 0x7f800000u) c.a = 0.0;
  }
  bvec4 nan = greaterThan(floatBitsToUint(c) & uvec4(0x7fffffffu), uvec4(0x7f800000u));
  return clamp(mix(c, vec4(0.0), nan), vec4(-65504.0), vec4(65504.0));
}
)glsl";

}  // namespace pfx_bloom::shaders
