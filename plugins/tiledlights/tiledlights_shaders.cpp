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
layout(location = 8) uniform uint capacity;
layout(location = 11) uniform mat4 inverse_view;
layout(location = 12) uniform int base_mode;
layout(location = 13) uniform int show;
out vec4 result;

// show = list_heat: log2(1 + count) / 10 through black, blue, green, yellow, red (1023 and more).
vec3 list_heat(uint count) {
  const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), vec3(1.0, 1.0, 0.0),
                                vec3(1.0, 0.0, 0.0));
  float t = clamp(log2(1.0 + float(count)) / 10.0, 0.0, 1.0) * 4.0;
  int i = min(int(t), 3);
  return mix(stops[i], stops[i + 1], t - float(i));
}

// Seed 003's point light: 1 / (1 + d^2), faded to exactly 0 over the last quarter of the range.
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
  vec4 color = texelFetch(color_in, pixel, 0);
  float d = view_depth(texelFetch(depth_in, pixel, 0).r);
  if (!has_geometry(d)) {
    result = color;
    return;
  }
  vec3 p = (inverse_view * vec4(ray_slope(gl_FragCoord.xy) * d, -d, 1.0)).xyz;
  vec3 n = texelFetch(normal_in, pixel, 0).xyz;
  float n_length = length(n);
  n = n_length > 0.0 ? n / n_length : vec3(0.0);

  uint offset = 0u, count = light_count;
  bool listed = false;
  if (list_mode != 0) {
    ivec2 t = list_mode == 2 ? (pixel * tiles) / frame_size : pixel / tile_size;
    int list = t.y * tiles.x + t.x;
    if (list_mode == 3) list += slice_of(d) * tiles.x * tiles.y;
    uvec2 head = heads[list];
    // A list longer than its capacity was not stored: every light instead, the same sum.
    if (head.y <= capacity) {
      offset = head.x;
      count = head.y;
      listed = true;
    }
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
  vec3 base = base_mode == 1 ? texelFetch(emissive_in, pixel, 0).rgb : color.rgb;
  result = vec4(base + texelFetch(albedo_in, pixel, 0).rgb * sum, color.a);
}
)";

// What both list builders share: one work group per screen tile, the tile's depth bounds, its
// side planes, and an ordered compaction so every list is in increasing light order (the order
// brute force sums in).
const char* kCullCommon = R"(
layout(local_size_x = 256) in;
layout(binding = 0) uniform sampler2D depth_in;
layout(std430, binding = 1) writeonly buffer Heads { uvec2 heads[]; };
layout(std430, binding = 2) writeonly buffer Indices { uint indices[]; };
layout(std430, binding = 3) buffer Stats { uint overflowed; uint entries; uint longest; uint unused; };
layout(location = 6) uniform ivec2 tile_size;
layout(location = 7) uniform ivec2 tiles;
layout(location = 8) uniform uint capacity;

shared uint depth_min_bits, depth_max_bits;
shared uint scan[256];

// Bounds of the positive finite depths in the tile (floats >= 0 order like their bits).
void tile_depth_bounds(ivec2 origin, ivec2 size, out float near_depth, out float far_depth, out bool empty) {
  uint id = gl_LocalInvocationIndex;
  if (id == 0u) {
    depth_min_bits = 0x7f800000u;
    depth_max_bits = 0u;
  }
  barrier();
  for (int k = int(id); k < size.x * size.y; k += 256) {
    float d = view_depth(texelFetch(depth_in, origin + ivec2(k % size.x, k / size.x), 0).r);
    if (has_geometry(d)) {
      atomicMin(depth_min_bits, floatBitsToUint(d));
      atomicMax(depth_max_bits, floatBitsToUint(d));
    }
  }
  barrier();
  near_depth = uintBitsToFloat(depth_min_bits);
  far_depth = uintBitsToFloat(depth_max_bits);
  empty = depth_max_bits == 0u;
}

// Inward unit normals of the side planes of the frustum behind pixels [origin, origin + size).
void side_planes(ivec2 origin, ivec2 size, out vec3 planes[4]) {
  vec2 s0 = ray_slope(vec2(origin)), s1 = ray_slope(vec2(origin + size));
  planes[0] = normalize(vec3(1.0, 0.0, s0.x));
  planes[1] = normalize(vec3(-1.0, 0.0, -s1.x));
  planes[2] = normalize(vec3(0.0, 1.0, s0.y));
  planes[3] = normalize(vec3(0.0, -1.0, -s1.y));
}

bool sphere_in_tile(vec4 sphere, vec3 planes[4], float near_depth, float far_depth) {
  float depth = -sphere.z;
  if (depth + sphere.w < near_depth || depth - sphere.w > far_depth) return false;
  for (int i = 0; i < 4; ++i)
    if (dot(planes[i], sphere.xyz) < -sphere.w) return false;
  return true;
}

// Rank of this invocation's flag among the set flags of the group (an exclusive prefix sum),
// and their total. Called by every invocation.
uint rank_of(bool flag, out uint total) {
  uint id = gl_LocalInvocationIndex;
  scan[id] = flag ? 1u : 0u;
  barrier();
  for (uint step = 1u; step < 256u; step <<= 1) {
    uint add = id >= step ? scan[id - step] : 0u;
    barrier();
    scan[id] += add;
    barrier();
  }
  total = scan[255];
  uint rank = scan[id] - (flag ? 1u : 0u);
  barrier();
  return rank;
}

void record(uint list, uint count) {
  heads[list] = uvec2(list * capacity, count);
  if (count > capacity) atomicAdd(overflowed, 1u);
  atomicAdd(entries, count);
  atomicMax(longest, count);
}
)";

const char* kTiled = R"(
void main() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * tile_size;
  ivec2 size = min(tile_size, frame_size - origin);
  float near_depth, far_depth;
  bool empty;
  tile_depth_bounds(origin, size, near_depth, far_depth, empty);
  vec3 planes[4];
  side_planes(origin, size, planes);
  uint list = gl_WorkGroupID.y * uint(tiles.x) + gl_WorkGroupID.x;
  uint first_index = list * capacity;
  uint count = 0u;
  if (!empty) {
    for (uint first = 0u; first < light_count; first += 256u) {
      uint i = first + gl_LocalInvocationIndex;
      bool hit = i < light_count && sphere_in_tile(lights[i].view_cull, planes, near_depth, far_depth);
      uint total;
      uint rank = rank_of(hit, total);
      if (hit && count + rank < capacity) indices[first_index + count + rank] = i;
      count += total;
    }
  }
  if (gl_LocalInvocationIndex == 0u) record(list, count);
}
)";

const char* kClustered = R"(
shared uint candidates[256];
shared uint slice_count[64];

// The view depths slice s covers, widened by 0.1% so a pixel whose slice index rounds to a
// neighbour is still inside the list it reads.
float slice_near(int s) { return s == 0 ? 0.0 : slice_range.x * exp(slice_range.y * float(s) / float(slices)) * 0.999; }
float slice_far(int s) {
  return s == slices - 1 ? uintBitsToFloat(0x7f800000u)
                         : slice_range.x * exp(slice_range.y * float(s + 1) / float(slices)) * 1.001;
}

// Appends light i to the cluster's list when its sphere reaches the cluster's depths.
void consider(uint i, float z0, float z1, uint list, inout uint count) {
  vec4 sphere = lights[i].view_cull;
  float depth = -sphere.z;
  if (depth + sphere.w < z0 || depth - sphere.w > z1) return;
  if (count < capacity) indices[list * capacity + count] = i;
  ++count;
}

void main() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * tile_size;
  ivec2 size = min(tile_size, frame_size - origin);
  float near_depth, far_depth;
  bool empty;
  tile_depth_bounds(origin, size, near_depth, far_depth, empty);
  vec3 planes[4];
  side_planes(origin, size, planes);
  int s = int(gl_LocalInvocationIndex);
  // The slices this tile's pixels fall in; the others stay empty.
  bool mine = s < slices && !empty && s >= slice_of(near_depth * 0.999) && s <= slice_of(far_depth * 1.001);
  float z0 = mine ? max(slice_near(s), near_depth) : 0.0;
  float z1 = mine ? min(slice_far(s), far_depth) : 0.0;
  uint tile = gl_WorkGroupID.y * uint(tiles.x) + gl_WorkGroupID.x;
  uint list = uint(s) * uint(tiles.x * tiles.y) + tile;
  if (s < slices) slice_count[s] = 0u;
  barrier();
  if (!empty) {
    for (uint first = 0u; first < light_count; first += 256u) {
      uint i = first + gl_LocalInvocationIndex;
      bool hit = i < light_count && sphere_in_tile(lights[i].view_cull, planes, near_depth, far_depth);
      uint total;
      uint rank = rank_of(hit, total);
      if (hit) candidates[rank] = i;
      barrier();
      // One invocation per slice walks the tile's candidates in order: its list stays sorted.
      if (mine) {
        uint count = slice_count[s];
        uint k = 0u;
        // Sixteen candidates a turn, for llvmpipe's loop guard (see the shading pass).
#define TERM(j) consider(candidates[k + j], z0, z1, list, count);
        for (; k + 16u <= total; k += 16u) { SIXTEEN_TERMS }
#undef TERM
        for (; k < total; ++k) consider(candidates[k], z0, z1, list, count);
        slice_count[s] = count;
      }
      barrier();
    }
  }
  if (s < slices) record(list, slice_count[s]);
}
)";

}  // namespace

std::string shade_fragment() { return std::string(kCommon) + kShade; }
std::string tiled_compute() { return std::string(kCommon) + kCullCommon + kTiled; }
std::string clustered_compute() { return std::string(kCommon) + kCullCommon + kClustered; }

}  // namespace pfx_tiledlights::shaders
