#include "tiledlights_shaders.hpp"

namespace pfx_tiledlights::shaders {
namespace {

// What every program shares: the light buffer, the frame's geometry and depth decoding.
const char* kCommon = R"(#version 450 core
struct Light {
  vec4 world_range;  // world position, range (the window is 0 from there on)
  vec4 radiance;     // colour x intensity
  vec4 view_cull;    // view-space centre, culling radius (range plus a rounding margin)
};
layout(std430, binding = 0) readonly buffer Lights { Light lights[]; };
layout(location = 0) uniform uint light_count;
layout(location = 1) uniform int depth_encoding;
layout(location = 2) uniform vec2 near_far;
layout(location = 3) uniform vec4 perspective;  // scale x, scale y, offset x, offset y
layout(location = 4) uniform ivec2 frame_size;
layout(location = 9) uniform int slices;
layout(location = 10) uniform vec2 slice_range;  // near depth of slicing, log(far / near)

// The twin of pfx_view_depth (pfx/depth.h): linear view depth, +inf where nothing is.
float view_depth(float stored) {
  const float inf = uintBitsToFloat(0x7f800000u);
  float n = near_far.x, f = near_far.y;
  if (depth_encoding == 3) return stored;
  if (depth_encoding == 1) {
    float z = 2.0 * stored - 1.0;
    if (isinf(f)) return z >= 1.0 ? inf : 2.0 * n / (1.0 - z);
    float denom = (f + n) - z * (f - n);
    return denom <= 0.0 ? inf : 2.0 * n * f / denom;
  }
  if (depth_encoding == 2) {
    if (stored < 0.0) return inf;
    if (isinf(f)) return stored == 0.0 ? inf : n / stored;
    return n * f / (stored * (f - n) + n);
  }
  return uintBitsToFloat(0x7fc00000u);
}

// Only a positive, finite depth is a surface; NaN, 0, negative and +inf are "nothing here".
bool has_geometry(float d) { return d > 0.0 && !isinf(d); }

// x_view / depth and y_view / depth of the ray through a window position.
vec2 ray_slope(vec2 window) {
  return (2.0 * window / vec2(frame_size) - 1.0 + perspective.zw) / perspective.xy;
}

#define SIXTEEN_TERMS TERM(0u) TERM(1u) TERM(2u) TERM(3u) TERM(4u) TERM(5u) TERM(6u) TERM(7u) \
  TERM(8u) TERM(9u) TERM(10u) TERM(11u) TERM(12u) TERM(13u) TERM(14u) TERM(15u)

int slice_of(float d) {
  float s = floor(log(d / slice_range.x) / slice_range.y * float(slices));
  return int(clamp(s, 0.0, float(slices - 1)));
}
)";

const char* kShade = R"(
layout(binding = 0) uniform sampler2D color_in;
layout(binding = 1) uniform sampler2D depth_in;
layout(binding = 2) uniform sampler2D normal_in;
layout(binding = 3) uniform sampler2D albedo_in;
layout(binding = 4) uniform sampler2D emissive_in;
layout(std430, binding = 1) readonly buffer Heads { uvec2 heads[]; };
layout(std430, binding = 2) readonly buffer Indices { uint indices[]; };
layout(location = 5) uniform int list_mode;
layout(location = 6) uniform ivec2 tile_size;
layout(location = 7) uniform ivec2 tiles;
layout(location = 11) uniform mat4 inverse_view;
layout(location = 12) uniform int base_mode;
layout(location = 13) uniform int show;
layout(location = 14) uniform int nonfinite;  // 0 zero, 1 clamp
out vec4 result;

// A colour sample as the nonfinite policy reads it. zero: every non-finite channel is 0; clamp:
// NaN is 0 and +-Inf the largest half float, +-65504. Finite channels are unchanged. Tested on the
// bits: a compiler may assume floats are finite and fold isnan() and isinf() away.
vec4 finite_sample(vec4 c) {
  uvec4 bits = floatBitsToUint(c);
  bvec4 bad = equal(bits & 0x7f800000u, uvec4(0x7f800000u));
  bvec4 nan = bvec4(uvec4(bad) & uvec4(notEqual(bits & 0x007fffffu, uvec4(0u))));
  vec4 replaced = nonfinite == 1 ? mix(sign(c) * 65504.0, vec4(0.0), nan) : vec4(0.0);
  return mix(c, replaced, bad);
}

// A normal with a non-finite component lights nothing (as a zero normal does).
vec3 usable_normal(vec3 n) {
  if (any(equal(floatBitsToUint(n) & 0x7f800000u, uvec3(0x7f800000u)))) return vec3(0.0);
  float n_length = length(n);
  return n_length > 0.0 ? n / n_length : vec3(0.0);
}

// show = list_heat: log2(1 + count) / 10 through black, blue, green, yellow, red (1023 and more).
vec3 list_heat(uint count) {
  const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), vec3(1.0, 1.0, 0.0),
                                vec3(1.0, 0.0, 0.0));
  float t = clamp(log2(1.0 + float(count)) / 10.0, 0.0, 1.0) * 4.0;
  int i = min(int(t), 3);
  return mix(stops[i], stops[i + 1], t - float(i));
}

// The point light: 1 / (1 + d^2), faded to exactly 0 over the last quarter of the range.
vec3 light_term(Light light, vec3 p, vec3 n) {
  vec3 l = light.world_range.xyz - p;
  float d2 = dot(l, l);
  float d = sqrt(d2);
  float r = light.world_range.w;
  float t = clamp((d - 0.75 * r) / (0.25 * r), 0.0, 1.0);
  float window = 1.0 - t * t * (3.0 - 2.0 * t);
  float theta = d2 > 0.0 ? max(dot(n, l) / d, 0.0) : 1.0;
  return light.radiance.rgb * (theta * window / (1.0 + d2));
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 color = finite_sample(texelFetch(color_in, pixel, 0));
  float d = view_depth(texelFetch(depth_in, pixel, 0).r);
  if (!has_geometry(d)) {
    result = color;
    return;
  }
  vec3 p = (inverse_view * vec4(ray_slope(gl_FragCoord.xy) * d, -d, 1.0)).xyz;
  vec3 n = usable_normal(texelFetch(normal_in, pixel, 0).xyz);

  // Every list holds all the lights of its tile or cluster, however many (one compact index array).
  uint offset = 0u, count = light_count;
  bool listed = list_mode != 0;
  if (listed) {
    ivec2 t = list_mode == 2 ? (pixel * tiles) / frame_size : pixel / tile_size;
    int list = t.y * tiles.x + t.x;
    if (list_mode == 3) list += slice_of(d) * tiles.x * tiles.y;
    uvec2 head = heads[list];
    offset = head.x;
    count = head.y;
  }
  if (show == 1) {
    result = vec4(list_heat(count), color.a);
    return;
  }
  // Sixteen terms a turn, written out: Mesa's llvmpipe ends a shader invocation's loops after
  // 65535 turns in all (its guard against endless shaders), which would otherwise silently drop
  // the lights of a pixel past the 65535th. The order of the sum stays the lights' order.
  vec3 sum = vec3(0.0);
  uint k = 0u;
  if (listed) {
#define TERM(j) sum += light_term(lights[indices[offset + k + j]], p, n);
    for (; k + 16u <= count; k += 16u) { SIXTEEN_TERMS }
#undef TERM
    for (; k < count; ++k) sum += light_term(lights[indices[offset + k]], p, n);
  } else {
#define TERM(j) sum += light_term(lights[k + j], p, n);
    for (; k + 16u <= count; k += 16u) { SIXTEEN_TERMS }
#undef TERM
    for (; k < count; ++k) sum += light_term(lights[k], p, n);
  }
  vec3 base = base_mode == 1 ? finite_sample(texelFetch(emissive_in, pixel, 0)).rgb : color.rgb;
  result = vec4(base + finite_sample(texelFetch(albedo_in, pixel, 0)).rgb * sum, color.a);
}
)";

}  // namespace

std::string common_source() { return kCommon; }
std::string shade_fragment() { return std::string(kCommon) + kShade; }

}  // namespace pfx_tiledlights::shaders
