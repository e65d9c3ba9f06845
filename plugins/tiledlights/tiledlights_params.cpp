#include "tiledlights_params.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_tiledlights {
namespace {

using pfx::desc::param;
using pfx::desc::with_items;

const pfx_enum_item kModeItems[MODE_COUNT] = {
    {"brute", "Brute force: every light at every pixel"},
    {"cpu8x4", "Seed 003: sub-frustum grid culled on the CPU"},
    {"tiled", "GPU tiles with depth bounds (compute)"},
    {"clustered", "GPU clusters: tiles x exponential depth slices (compute)"}};

const pfx_enum_item kRangeItems[] = {{"cutoff", "Where the light falls below the cutoff"},
                                     {"seed", "Seed 003: 3 sqrt(max colour)"}};

const pfx_enum_item kBaseItems[] = {{"color", "Add to the incoming colour"},
                                    {"emissive", "Add to the emissive input"}};

const pfx_enum_item kShowItems[] = {{"light", "The lit image"},
                                    {"list_heat", "Heat colour of the lights each pixel sums"}};

const pfx_enum_item kNonfiniteItems[] = {{"zero", "A non-finite sample is read as 0"},
                                         {"clamp", "NaN is read as 0, +-Inf as +-65504"}};

}  // namespace

const char* const kModeNames[MODE_COUNT] = {"brute", "cpu8x4", "tiled", "clustered"};

const pfx_param_desc kParams[PARAM_COUNT] = {
    with_items(param("mode", "Mode",
                     "How the lights reaching a pixel are found. brute: all of them (the baseline); cpu8x4: "
                     "seed 003's grid of sub-frustums culled on the CPU; tiled: per-tile lists built on the "
                     "GPU with the tile's depth range; clustered: per-cluster lists (tiles x depth slices). "
                     "Every mode gives the brute-force image.",
                     "", "Lights", PFX_PARAM_ENUM, 0, MODE_COUNT - 1, 0, MODE_COUNT - 1, 1, {{MODE_TILED}}),
               kModeItems, MODE_COUNT),
    with_items(param("range_rule", "Range rule",
                     "How far a light without an explicit range reaches. cutoff: until intensity x max(colour) "
                     "/ (1 + d^2) falls to the cutoff; seed: 3 sqrt(intensity x max(colour)), seed 003's rule. "
                     "Light is faded out over the last quarter of the range.",
                     "", "Lights", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{RANGE_CUTOFF}}),
               kRangeItems, 2),
    param("cutoff", "Cutoff",
          "With the cutoff rule: the light level below which a light is ignored. Smaller is closer to the "
          "physical (unlimited) falloff and slower.",
          "", "Lights", PFX_PARAM_FLOAT, 1e-6, 1e6, 0.001, 1, 0.001, {{0.05}}),
    with_items(param("base", "Base",
                     "What the lights are added to: the incoming colour (which the host's G-buffer fills with "
                     "emissive + ambient x albedo) or the emissive input alone. Where there is no geometry "
                     "the incoming colour passes through either way.",
                     "", "Lights", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{BASE_COLOR}}),
               kBaseItems, 2),
    param("tile_size", "Tile size", "tiled: the side of a screen tile in pixels.", "px", "Culling", PFX_PARAM_INT, 4,
          128, 8, 64, 1, {{16}}),
    param("cpu_tiles_x", "CPU tiles across", "cpu8x4: sub-frustums across the frame (the seed's 8).", "",
          "Culling", PFX_PARAM_INT, 1, 256, 1, 64, 1, {{8}}),
    param("cpu_tiles_y", "CPU tiles down", "cpu8x4: sub-frustums down the frame (the seed's 4).", "", "Culling",
          PFX_PARAM_INT, 1, 256, 1, 64, 1, {{4}}),
    param("cluster_tile_size", "Cluster tile size", "clustered: the side of a cluster's screen tile in pixels.",
          "px", "Culling", PFX_PARAM_INT, 8, 256, 16, 128, 1, {{64}}),
    param("slices", "Depth slices",
          "clustered: depth slices between the near and the far plane, exponentially spaced (a far plane "
          "at infinity slices up to 1000 x near).",
          "", "Culling", PFX_PARAM_INT, 1, 64, 1, 64, 1, {{16}}),
    param("max_list_indices", "Most list indices",
          "tiled, clustered: the most light indices all lists of a frame may hold together (a memory budget; "
          "4 bytes each, per buffered frame). 0: as many as the GL's shader storage block size allows. Each "
          "list holds every light of its tile or cluster; a frame that needs more than this is refused with "
          "an error, never cut short.",
          "", "Culling", PFX_PARAM_INT, 0, 1073741823, 0, 16777216, 1, {{0}}),
    with_items(param("show", "Show",
                     "light: the lit image. list_heat: instead of the light, a heat colour of how many lights "
                     "each pixel with geometry sums (its tile's or cluster's list; every light for brute "
                     "force), on a log scale: black 0, blue 4, green 31, yellow 180, red 1023 or more.",
                     "", "Debug", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{SHOW_LIGHT}}),
               kShowItems, 2),
    with_items(param("nonfinite", "Non-finite input",
                     "How a NaN or infinite sample of the colour, emissive or albedo input is read, before "
                     "anything else. zero: every non-finite channel is 0; clamp: NaN is 0, +-Inf is +-65504 "
                     "(the largest half float). A non-finite normal lights nothing either way.",
                     "", "Input", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{NONFINITE_ZERO}}),
               kNonfiniteItems, 2),
};

Settings settings_from(const pfx_value* values) {
  Settings s;
  s.mode = static_cast<int>(values[PARAM_MODE].v[0]);
  s.range_rule = static_cast<int>(values[PARAM_RANGE_RULE].v[0]);
  s.cutoff = values[PARAM_CUTOFF].v[0];
  s.base = static_cast<int>(values[PARAM_BASE].v[0]);
  s.tile_size = static_cast<int>(values[PARAM_TILE_SIZE].v[0]);
  s.cpu_tiles_x = static_cast<int>(values[PARAM_CPU_TILES_X].v[0]);
  s.cpu_tiles_y = static_cast<int>(values[PARAM_CPU_TILES_Y].v[0]);
  s.cluster_tile_size = static_cast<int>(values[PARAM_CLUSTER_TILE_SIZE].v[0]);
  s.slices = static_cast<int>(values[PARAM_SLICES].v[0]);
  s.max_list_indices = values[PARAM_MAX_LIST_INDICES].v[0];
  s.show = static_cast<int>(values[PARAM_SHOW].v[0]);
  s.nonfinite = static_cast<int>(values[PARAM_NONFINITE].v[0]);
  return s;
}

}  // namespace pfx_tiledlights
