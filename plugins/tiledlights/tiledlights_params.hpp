// The "tiledlights" effect's parameters: indices into the descriptor table (and so into the value
// array the host passes), the enums' item indices, and the settings read out of the values once, so
// the GPU passes and the CPU references interpret them identically.
#pragma once

#include <cstdint>

#include <pfx/params.h>

namespace pfx_tiledlights {

enum Param : uint32_t {
  PARAM_MODE,
  PARAM_RANGE_RULE,
  PARAM_CUTOFF,
  PARAM_BASE,
  PARAM_TILE_SIZE,
  PARAM_CPU_TILES_X,
  PARAM_CPU_TILES_Y,
  PARAM_CLUSTER_TILE_SIZE,
  PARAM_SLICES,
  PARAM_MAX_LIST_INDICES,
  PARAM_SHOW,
  PARAM_NONFINITE,
  PARAM_COUNT
};

enum Mode : int { MODE_BRUTE = 0, MODE_CPU8X4 = 1, MODE_TILED = 2, MODE_CLUSTERED = 3, MODE_COUNT = 4 };
enum RangeRule : int { RANGE_CUTOFF = 0, RANGE_SEED = 1 };
// What the lights are added to: the incoming colour (the host's emissive + ambient, or an earlier
// lighting pass) or the emissive input alone.
enum Base : int { BASE_COLOR = 0, BASE_EMISSIVE = 1 };
// What the output shows: the lit image, or a heat colour of how many lights each pixel sums (its
// list's length; every light for brute force): where the cost goes.
enum Show : int { SHOW_LIGHT = 0, SHOW_LIST_HEAT = 1 };
// How a non-finite sample of the colour, emissive or albedo input is read: zero: as 0 (every
// non-finite channel); clamp: NaN as 0, +-Inf as +-65504 (the largest half float).
enum Nonfinite : int { NONFINITE_ZERO = 0, NONFINITE_CLAMP = 1 };

extern const pfx_param_desc kParams[PARAM_COUNT];
extern const char* const kModeNames[MODE_COUNT];

struct Settings {
  int mode = MODE_TILED;
  int range_rule = RANGE_CUTOFF;
  double cutoff = 0.05;
  int base = BASE_COLOR;
  int tile_size = 16;          // tiled: pixels per side
  int cpu_tiles_x = 8;         // cpu8x4: the grid over the whole frame
  int cpu_tiles_y = 4;
  int cluster_tile_size = 64;  // clustered: pixels per side of a cluster's screen tile
  int slices = 16;             // clustered: exponential depth slices
  double max_list_indices = 0; // tiled and clustered: the most indices all lists may hold (0: the GL's limit)
  int show = SHOW_LIGHT;
  int nonfinite = NONFINITE_ZERO;
};

Settings settings_from(const pfx_value* values);

}  // namespace pfx_tiledlights
