// GLSL of the "tiledlights" effect: the shading pass every mode shares (what differs is where a
// pixel's light list comes from) and the two compute passes that build lists on the GPU.
#pragma once

#include <string>

namespace pfx_tiledlights::shaders {

// Bindings shared by the C++ side and the shaders.
enum Binding : int {
  SSBO_LIGHTS = 0,   // GpuLight[]
  SSBO_HEADS = 1,    // uvec2 (offset, count) per tile or cluster
  SSBO_INDICES = 2,  // uint light indices
  SSBO_STATS = 3,    // uint[4]: lists over capacity, entries, longest list, (unused)
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
  U_CAPACITY = 8,            // uint: a list longer than this was not stored: use every light
  U_SLICES = 9,              // int
  U_SLICE_RANGE = 10,        // vec2: near depth of slicing, log(far / near)
  U_INVERSE_VIEW = 11,       // mat4
  U_BASE = 12,               // int: 0 colour, 1 emissive
  U_SHOW = 13,               // int: 0 light, 1 list heat
};

enum ListMode : int { LIST_ALL = 0, LIST_TILES_BY_SIZE = 1, LIST_TILES_BY_GRID = 2, LIST_CLUSTERS = 3 };

std::string shade_fragment();
std::string tiled_compute();
std::string clustered_compute();

// Work-group size of both compute passes: also the number of lights tested per step.
constexpr int kGroupSize = 256;

}  // namespace pfx_tiledlights::shaders
