// GLSL of the "tiledlights" effect: the shading pass every mode shares (what differs is where a
// pixel's light list comes from) and the compute passes that build lists on the GPU
// (cull_shaders.cpp): for tiles and for clusters a count phase and a fill phase of one program,
// and between them a prefix sum over the counts. The lists are one compact index array with an
// (offset, count) head per tile or cluster, so no list has a fixed size.
#pragma once

#include <string>

namespace pfx_tiledlights::shaders {

// Bindings shared by the C++ side and the shaders.
enum Binding : int {
  SSBO_LIGHTS = 0,   // GpuLight[]
  SSBO_HEADS = 1,    // uvec2 (offset, count) per tile or cluster
  SSBO_INDICES = 2,  // uint light indices, every list back to back
  SSBO_STATS = 3,    // uint[4]: entries, longest list, lists the fill phase found inconsistent, (unused)
  SSBO_BOUNDS = 4,   // uvec2 per screen tile: the bits of its geometry's nearest and farthest view depth
};

// Uniform locations.
enum Uniform : int {
  U_LIGHT_COUNT = 0,
  U_DEPTH_ENCODING = 1,
  U_NEAR_FAR = 2,            // vec2; far may be +infinity
  U_PERSPECTIVE = 3,         // vec4: scale x, scale y, offset x, offset y
  U_FRAME_SIZE = 4,          // ivec2
  U_LIST_MODE = 5,           // int: ListMode
  U_TILE_SIZE = 6,           // ivec2: pixels per tile (tiles by size) or unused
  U_TILES = 7,               // ivec2: tiles across, down
  U_INDEX_CAPACITY = 8,      // uint: indices the index buffer holds (the fill phase never writes past it)
  U_SLICES = 9,              // int
  U_SLICE_RANGE = 10,        // vec2: near depth of slicing, log(far / near)
  U_INVERSE_VIEW = 11,       // mat4
  U_BASE = 12,               // int: 0 colour, 1 emissive
  U_SHOW = 13,               // int: 0 light, 1 list heat
  U_NONFINITE = 14,          // int: Nonfinite
  U_PHASE = 15,              // int: Phase (list building)
  U_LIST_COUNT = 16,         // uint: lists (prefix sum)
};

enum ListMode : int { LIST_ALL = 0, LIST_TILES_BY_SIZE = 1, LIST_TILES_BY_GRID = 2, LIST_CLUSTERS = 3 };
// The two dispatches of a list-building program: count each list's lights (and record the tiles'
// depth bounds), then, after the prefix sum has placed the lists, write the indices.
enum Phase : int { PHASE_COUNT = 0, PHASE_FILL = 1 };

std::string shade_fragment();
std::string tiled_compute();
std::string clustered_compute();
std::string prefix_sum_compute();

// What every program shares: the light buffer, the frame's geometry and depth decoding.
std::string common_source();

// Work-group size of the list-building passes.
constexpr int kGroupSize = 256;

}  // namespace pfx_tiledlights::shaders
