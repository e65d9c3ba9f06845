#include "dof_shaders.hpp"

#include <cstdio>

#include "dof_seed_disk.hpp"

namespace pfx_dof::shaders {

// Not-a-number and infinity are tested on the bits: a compiler may assume floats are finite and
// fold isnan() and isinf() away.
const char* const kCommon = R"glsl(#version 450 core
layout(location = 0) uniform int u_encoding;
layout(location = 1) uniform vec2 u_planes;
layout(location = 2) uniform int u_far_infinite;
layout(location = 3) uniform float u_max_coc;
layout(location = 0) out vec4 o_color;

const float k_half_max = 65504.0;

bool is_nan(float v) { return (floatBitsToUint(v) & 0x7fffffffu) > 0x7f800000u; }
bool is_inf(float v) { return (floatBitsToUint(v) & 0x7fffffffu) == 0x7f800000u; }
float infinity() { return uintBitsToFloat(0x7f800000u); }

vec4 safe_color(vec4 c) {
  bvec4 nan = greaterThan(floatBitsToUint(c) & uvec4(0x7fffffffu), uvec4(0x7f800000u));
  return clamp(mix(c, vec4(0.0), nan), vec4(-k_half_max), vec4(k_half_max));
}

// pfx_view_depth (pfx/depth.h): 1 standard hardware, 2 reversed, 3 linear metres.
float view_depth(float stored) {
  if (u_encoding == 3) return stored;
  float n = u_planes.x, f = u_planes.y;
  if (u_encoding == 1) {
    float z = 2.0 * stored - 1.0;
    if (u_far_infinite != 0) return z >= 1.0 ? infinity() : 2.0 * n / (1.0 - z);
    float denom = (f + n) - z * (f - n);
    return denom <= 0.0 ? infinity() : 2.0 * n * f / denom;
  }
  if (stored < 0.0) return infinity();
  if (u_far_infinite != 0) return stored == 0.0 ? infinity() : n / stored;
  return n * f / (stored * (f - n) + n);
}

// Signed CoC diameter in frame pixels (dof_camera.hpp: C (1/P - 1/D), clamped; NaN depth -> 0,
// depth <= 0 -> the nearest blur).
float coc_of(vec2 lens, float depth) {
  if (is_nan(depth)) return 0.0;
  if (depth <= 0.0) return -u_max_coc;
  float inverse = is_inf(depth) ? 0.0 : 1.0 / depth;
  return clamp(lens.x * (lens.y - inverse), -u_max_coc, u_max_coc);
}
)glsl";

const char* const kLens = R"glsl(
layout(binding = 0) uniform sampler2D u_depth;
layout(location = 4) uniform vec4 u_camera;
layout(location = 5) uniform ivec2 u_focus_texel;
layout(location = 6) uniform int u_autofocus;
layout(location = 7) uniform vec2 u_focus_range;

void main() {
  float p = u_camera.w;
  if (u_autofocus != 0) {
    float d = view_depth(texelFetch(u_depth, u_focus_texel, 0).r);
    if (!is_nan(d)) p = clamp(d, u_focus_range.x, u_focus_range.y);
  }
  float image_distance = u_camera.x, inverse_focus = 1.0 / p;
  float scale = image_distance * image_distance * u_camera.y / (u_camera.z * (1000.0 + image_distance * inverse_focus));
  o_color = vec4(scale, inverse_focus, 0.0, 0.0);
}
)glsl";

// Bilinear by hand from four safe texels: one NaN texel would poison GL_LINEAR's mix.
const char* const kSeedHalf = R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(location = 4) uniform vec2 u_out_size;

void main() {
  ivec2 size = textureSize(u_color, 0);
  vec2 q = gl_FragCoord.xy / u_out_size * vec2(size) - 0.5;
  vec2 base = floor(q), f = q - base;
  ivec2 i = ivec2(base), hi = size - 1;
  vec4 a = safe_color(texelFetch(u_color, clamp(i, ivec2(0), hi), 0));
  vec4 b = safe_color(texelFetch(u_color, clamp(i + ivec2(1, 0), ivec2(0), hi), 0));
  vec4 c = safe_color(texelFetch(u_color, clamp(i + ivec2(0, 1), ivec2(0), hi), 0));
  vec4 d = safe_color(texelFetch(u_color, clamp(i + ivec2(1, 1), ivec2(0), hi), 0));
  o_color = mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}
)glsl";

std::string seed_body() {
  std::string disk;
  for (int i = 0; i < kSeedTaps; ++i) {
    char item[64];
    std::snprintf(item, sizeof item, "%svec2(%.3f, %.3f)", i ? ", " : "", kSeedDisk[i][0], kSeedDisk[i][1]);
    disk += item;
  }
  return "const vec2 k_disk[16] = vec2[16](" + disk + ");\n" + R"glsl(
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_half;
layout(binding = 3) uniform sampler2D u_lens;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 size = vec2(textureSize(u_color, 0));
  vec4 sharp = safe_color(texelFetch(u_color, p, 0));
  float coc = abs(coc_of(texelFetch(u_lens, ivec2(0), 0).xy, view_depth(texelFetch(u_depth, p, 0).r)));
  o_color = sharp;
  if (coc > 1.0) {
    vec2 uv = gl_FragCoord.xy / size, scale = coc / size;
    vec3 blur = vec3(0.0);
    for (int i = 0; i < 16; ++i) blur += texture(u_half, uv + k_disk[i] * scale).rgb;
    o_color.rgb = mix(sharp.rgb, blur * (1.0 / 16.0), clamp(coc - 1.0, 0.0, 1.0));
  }
}
)glsl";
}

}  // namespace pfx_dof::shaders
