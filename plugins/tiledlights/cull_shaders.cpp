// The list-building compute passes: one work group per screen tile. The count phase records the
// tile's depth bounds and each list's length; a prefix sum over the lengths gives every list its
// offset in one compact index array; the fill phase writes the indices there, each list in
// increasing light order (the order brute force sums in). Both phases run the same program and
// decide "this light reaches this tile (and slice)" with the same `precise` arithmetic from the
// same stored depth bounds, so the fill finds exactly the lights the count found.
#include "tiledlights_shaders.hpp"

namespace pfx_tiledlights::shaders {
namespace {

const char* kCullCommon = R"(
layout(local_size_x = 256) in;
layout(binding = 0) uniform sampler2D depth_in;
layout(std430, binding = 1) buffer Heads { uvec2 heads[]; };
layout(std430, binding = 2) writeonly buffer Indices { uint indices[]; };
layout(std430, binding = 3) buffer Stats { uint entries; uint longest; uint inconsistent; uint unused; };
layout(std430, binding = 4) buffer Bounds { uvec2 bounds[]; };
layout(location = 6) uniform ivec2 tile_size;
layout(location = 7) uniform ivec2 tiles;
layout(location = 8) uniform uint index_capacity;
layout(location = 15) uniform int phase;  // 0 count, 1 fill

shared uint depth_min_bits, depth_max_bits;
shared uint scan[256];

// The bounds of the positive finite depths in the tile (floats >= 0 order like their bits): found
// by the count phase, stored, and read back by the fill phase, so both cull against the same ones.
void tile_depth_bounds(uint tile, ivec2 origin, ivec2 size, out float near_depth, out float far_depth,
                       out bool empty) {
  uint id = gl_LocalInvocationIndex;
  if (phase == 0) {
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
    if (id == 0u) bounds[tile] = uvec2(depth_min_bits, depth_max_bits);
    near_depth = uintBitsToFloat(depth_min_bits);
    far_depth = uintBitsToFloat(depth_max_bits);
    empty = depth_max_bits == 0u;
  } else {
    uvec2 b = bounds[tile];
    near_depth = uintBitsToFloat(b.x);
    far_depth = uintBitsToFloat(b.y);
    empty = b.y == 0u;
  }
}

// Inward unit normals of the side planes of the frustum behind pixels [origin, origin + size).
void side_planes(ivec2 origin, ivec2 size, out vec3 planes[4]) {
  precise vec2 s0 = ray_slope(vec2(origin)), s1 = ray_slope(vec2(origin + size));
  planes[0] = normalize(vec3(1.0, 0.0, s0.x));
  planes[1] = normalize(vec3(-1.0, 0.0, -s1.x));
  planes[2] = normalize(vec3(0.0, 1.0, s0.y));
  planes[3] = normalize(vec3(0.0, -1.0, -s1.y));
}

bool reaches_depths(vec4 sphere, float z0, float z1) {
  precise float depth = -sphere.z;
  precise float deepest = depth + sphere.w;
  precise float nearest = depth - sphere.w;
  return !(deepest < z0 || nearest > z1);
}

bool sphere_in_tile(vec4 sphere, vec3 planes[4], float near_depth, float far_depth) {
  if (!reaches_depths(sphere, near_depth, far_depth)) return false;
  for (int i = 0; i < 4; ++i) {
    precise float distance = dot(planes[i], sphere.xyz);
    if (distance < -sphere.w) return false;
  }
  return true;
}

// Exclusive prefix sum of one value per invocation over the group (Hillis-Steele), and the total.
// Called by every invocation.
uint group_prefix(uint value, out uint total) {
  uint id = gl_LocalInvocationIndex;
  scan[id] = value;
  barrier();
  for (uint step = 1u; step < 256u; step <<= 1) {
    uint add = id >= step ? scan[id - step] : 0u;
    barrier();
    scan[id] += add;
    barrier();
  }
  total = scan[255];
  uint before = scan[id] - value;
  barrier();
  return before;
}

// The fill phase found `found` lights for a list the count phase sized to head.y: they must agree
// (a disagreement is counted, and the report turns it into an error).
void check_filled(uvec2 head, uint found) {
  if (found != head.y) atomicAdd(inconsistent, 1u);
}
)";

// Tiles: the count phase counts each tile's lights; the fill phase gives each invocation a run of
// consecutive lights, counts its hits, places them with a prefix sum over the group and writes
// them, so the list comes out in light order.
const char* kTiled = R"(
void main() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * tile_size;
  ivec2 size = min(tile_size, frame_size - origin);
  uint tile = gl_WorkGroupID.y * uint(tiles.x) + gl_WorkGroupID.x;
  float near_depth, far_depth;
  bool empty;
  tile_depth_bounds(tile, origin, size, near_depth, far_depth, empty);
  vec3 planes[4];
  side_planes(origin, size, planes);
  uint id = gl_LocalInvocationIndex;
  uint per = (light_count + 255u) / 256u;
  uint first = min(id * per, light_count), last = min(first + per, light_count);
  uint mine = 0u;
  if (!empty)
    for (uint i = first; i < last; ++i)
      if (sphere_in_tile(lights[i].view_cull, planes, near_depth, far_depth)) ++mine;
  uint total;
  uint before = group_prefix(mine, total);
  if (phase == 0) {
    if (id == 0u) heads[tile] = uvec2(0u, total);
    return;
  }
  uvec2 head = heads[tile];
  if (id == 0u) check_filled(head, total);
  uint at = before;
  if (!empty)
    for (uint i = first; i < last; ++i)
      if (sphere_in_tile(lights[i].view_cull, planes, near_depth, far_depth)) {
        // Never past the list's own end, nor the buffer's: a disagreement cannot spill into
        // another list.
        if (at < head.y && head.x + at < index_capacity) indices[head.x + at] = i;
        ++at;
      }
}
)";

// Clusters: screen tiles x exponential depth slices. Both phases take the tile's lights 256 at a
// time; the count phase adds each to the slices it reaches; the fill phase compacts the chunk's
// lights in order and one invocation per slice walks them, so each slice's list stays sorted.
const char* kClustered = R"(
shared uint candidates[256];
shared uint slice_count[64];

// The view depths slice s covers, widened by 0.1% so a pixel whose slice index rounds to a
// neighbour is still inside the list it reads, and cut to the tile's depth bounds.
vec2 slice_depths(int s, float near_depth, float far_depth) {
  precise float z0 = s == 0 ? 0.0 : slice_range.x * exp(slice_range.y * float(s) / float(slices)) * 0.999;
  precise float z1 = s == slices - 1 ? uintBitsToFloat(0x7f800000u)
                                     : slice_range.x * exp(slice_range.y * float(s + 1) / float(slices)) * 1.001;
  return vec2(max(z0, near_depth), min(z1, far_depth));
}

// Appends light i to the slice's list when its sphere reaches the slice's depths.
void consider(uint i, vec2 z, uvec2 head, inout uint count) {
  if (!reaches_depths(lights[i].view_cull, z.x, z.y)) return;
  if (count < head.y && head.x + count < index_capacity) indices[head.x + count] = i;
  ++count;
}

// Counts light i (reaching the tile) in the tile's slices first..last it reaches.
#define COUNT_SLICE(s) if ((s) <= last && reaches_depths(sphere, z[(s) - first].x, z[(s) - first].y)) \
  atomicAdd(slice_count[s], 1u);

void main() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * tile_size;
  ivec2 size = min(tile_size, frame_size - origin);
  uint tile = gl_WorkGroupID.y * uint(tiles.x) + gl_WorkGroupID.x;
  float near_depth, far_depth;
  bool empty;
  tile_depth_bounds(tile, origin, size, near_depth, far_depth, empty);
  vec3 planes[4];
  side_planes(origin, size, planes);
  int s = int(gl_LocalInvocationIndex);
  // The slices this tile's pixels fall in; the others stay empty.
  int first = empty ? 0 : slice_of(near_depth * 0.999), last = empty ? -1 : slice_of(far_depth * 1.001);
  bool mine = s < slices && s >= first && s <= last;
  uint list = uint(s) * uint(tiles.x * tiles.y) + tile;
  if (s < slices) slice_count[s] = 0u;
  barrier();
  if (phase == 0) {
    vec2 z[64];
    for (int k = first; k <= last; ++k) z[k - first] = slice_depths(k, near_depth, far_depth);
    if (!empty)
      for (uint i = gl_LocalInvocationIndex; i < light_count; i += 256u) {
        vec4 sphere = lights[i].view_cull;
        if (!sphere_in_tile(sphere, planes, near_depth, far_depth)) continue;
        // Four slices a turn, for llvmpipe's loop guard (see the shading pass).
        for (int k = first; k <= last; k += 4) { COUNT_SLICE(k) COUNT_SLICE(k + 1) COUNT_SLICE(k + 2) COUNT_SLICE(k + 3) }
      }
    barrier();
    if (s < slices) heads[list] = uvec2(0u, slice_count[s]);
    return;
  }
  vec2 z = mine ? slice_depths(s, near_depth, far_depth) : vec2(0.0);
  uvec2 head = s < slices ? heads[list] : uvec2(0u);
  if (!empty) {
    for (uint chunk = 0u; chunk < light_count; chunk += 256u) {
      uint i = chunk + gl_LocalInvocationIndex;
      bool hit = i < light_count && sphere_in_tile(lights[i].view_cull, planes, near_depth, far_depth);
      uint total;
      uint rank = group_prefix(hit ? 1u : 0u, total);
      if (hit) candidates[rank] = i;
      barrier();
      // One invocation per slice walks the chunk's lights in order: its list stays sorted.
      if (mine) {
        uint count = slice_count[s];
        uint k = 0u;
        // Sixteen candidates a turn, for llvmpipe's loop guard (see the shading pass).
#define TERM(j) consider(candidates[k + j], z, head, count);
        for (; k + 16u <= total; k += 16u) { SIXTEEN_TERMS }
#undef TERM
        for (; k < total; ++k) consider(candidates[k], z, head, count);
        slice_count[s] = count;
      }
      barrier();
    }
  }
  if (s < slices) check_filled(head, slice_count[s]);
}
)";

// One work group: each invocation sums a run of consecutive list lengths, a prefix sum over the
// group places the runs, and each invocation writes its lists' offsets. Sums saturate at 2^32 - 1
// (the C++ side refuses a frame whose lists need that many).
const char* kPrefixSum = R"(#version 450 core
layout(local_size_x = 256) in;
layout(std430, binding = 1) buffer Heads { uvec2 heads[]; };
layout(std430, binding = 3) buffer Stats { uint entries; uint longest; uint inconsistent; uint unused; };
layout(location = 16) uniform uint list_count;
shared uint partial[256];

uint saturating_add(uint a, uint b) {
  uint sum = a + b;
  return sum < a ? 0xffffffffu : sum;
}

void main() {
  uint id = gl_LocalInvocationIndex;
  uint per = (list_count + 255u) / 256u;
  uint first = min(id * per, list_count), last = min(first + per, list_count);
  uint run = 0u, run_longest = 0u;
  for (uint l = first; l < last; ++l) {
    uint count = heads[l].y;
    run = saturating_add(run, count);
    run_longest = max(run_longest, count);
  }
  partial[id] = run;
  barrier();
  for (uint step = 1u; step < 256u; step <<= 1) {
    uint add = id >= step ? partial[id - step] : 0u;
    barrier();
    partial[id] = saturating_add(partial[id], add);
    barrier();
  }
  uint offset = id == 0u ? 0u : partial[id - 1u];
  for (uint l = first; l < last; ++l) {
    uint count = heads[l].y;
    heads[l].x = offset;
    offset = saturating_add(offset, count);
  }
  if (id == 255u) entries = partial[255];
  atomicMax(longest, run_longest);
}
)";

}  // namespace

std::string tiled_compute() { return common_source() + kCullCommon + kTiled; }
std::string clustered_compute() { return common_source() + kCullCommon + kClustered; }
std::string prefix_sum_compute() { return kPrefixSum; }

}  // namespace pfx_tiledlights::shaders
