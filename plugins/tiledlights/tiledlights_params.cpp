#include "tiledlights_params.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_tiledlights {
namespace {

using pfx::desc::param;

const pfx_enum_item kModeItems[MODE_COUNT] = {
    {"brute", "Brute force: every light at every pixel"},
    {"cpu8x4", "Tiled shading: sub-frustum grid culled on the CPU"},
    {"tiled", "GPU tiles with depth bounds (compute)"},
    {"clustered", "GPU clusters: tiles x exponential depth slices (compute)"}};

const pfx_enum_item kRangeItems[] = {{"cutoff", "Where the light falls below the cutoff"},
                                     {"seed", "3 sqrt(max colour): a fixed rule of thumb"}};

const pfx_enum_item kBaseItems[] = {{"color", "Add to the incoming colour"},
                                    {"emissive", "Add to the emissive input"}};

const pfx_enum_item kShowItems[] = {{"light", "The lit image"},
                                    {"list_heat", "Heat colour of the lights each pixel sums"}};

const pfx_enum_item kNonfiniteItems[] = {{"zero", "A non-finite sample is read as 0"},
                                         {"clamp", "NaN is read as 0, +-Inf as +-65504"}};

}  // namespace

const char* const kModeNames[MODE_COUNT] = {"brute", "cpu8x4", "tiled", "clustered"};

const pfx_param_desc kParams[PARAM_COUNT] = {
    param("mode")
        .label("Mode")
        .group("Lights")
        .tooltip("How the lights reaching a pixel are found. brute: all of them (the baseline); cpu8x4: "
                 "a grid of sub-frustums culled on the CPU (Olsson and Assarsson's tiled shading); tiled: "
                 "per-tile lists built on the GPU with the tile's depth range; clustered: per-cluster lists "
                 "(tiles x depth slices, Olsson's clustered shading). Every mode gives the brute-force image.")
        .items(kModeItems, MODE_COUNT)
        .default_value(MODE_TILED),
    param("range_rule")
        .label("Range rule")
        .group("Lights")
        .tooltip("How far a light without an explicit range reaches. cutoff: until intensity x max(colour) "
                 "/ (1 + d^2) falls to the cutoff; seed: 3 sqrt(intensity x max(colour)), a fixed rule of thumb. "
                 "Light is faded out over the last quarter of the range.")
        .items(kRangeItems, 2)
        .default_value(RANGE_CUTOFF),
    param("cutoff")
        .label("Cutoff")
        .group("Lights")
        .tooltip("With the cutoff rule: the light level below which a light is ignored. Smaller is closer to the "
                 "physical (unlimited) falloff and slower.")
        .float_range(1e-6, 1e6)
        .display_range(0.001, 1)
        .step(0.001)
        .default_value(0.05),
    param("base")
        .label("Base")
        .group("Lights")
        .tooltip("What the lights are added to: the incoming colour (which the host's G-buffer fills with "
                 "emissive + ambient x albedo) or the emissive input alone. Where there is no geometry "
                 "the incoming colour passes through either way.")
        .items(kBaseItems, 2)
        .default_value(BASE_COLOR),
    param("tile_size")
        .label("Tile size")
        .unit("px")
        .group("Culling")
        .tooltip("tiled: the side of a screen tile in pixels.")
        .int_range(4, 128)
        .display_range(8, 64)
        .default_value(16),
    param("cpu_tiles_x")
        .label("CPU tiles across")
        .group("Culling")
        .tooltip("cpu8x4: sub-frustums across the frame (8 by default).")
        .int_range(1, 256)
        .display_range(1, 64)
        .default_value(8),
    param("cpu_tiles_y")
        .label("CPU tiles down")
        .group("Culling")
        .tooltip("cpu8x4: sub-frustums down the frame (4 by default).")
        .int_range(1, 256)
        .display_range(1, 64)
        .default_value(4),
    param("cluster_tile_size")
        .label("Cluster tile size")
        .unit("px")
        .group("Culling")
        .tooltip("clustered: the side of a cluster's screen tile in pixels.")
        .int_range(8, 256)
        .display_range(16, 128)
        .default_value(64),
    param("slices")
        .label("Depth slices")
        .group("Culling")
        .tooltip("clustered: depth slices between the near and the far plane, exponentially spaced (a far plane "
                 "at infinity slices up to 1000 x near).")
        .int_range(1, 64)
        .default_value(16),
    param("max_list_indices")
        .label("Most list indices")
        .group("Culling")
        .tooltip("tiled, clustered: the most light indices all lists of a frame may hold together (a memory budget; "
                 "4 bytes each, per buffered frame). 0: as many as the GL's shader storage block size allows. Each "
                 "list holds every light of its tile or cluster; a frame that needs more than this is refused with "
                 "an error, never cut short.")
        .int_range(0, 1073741823)
        .display_range(0, 16777216)
        .default_value(0),
    param("show")
        .label("Show")
        .group("Debug")
        .tooltip("light: the lit image. list_heat: instead of the light, a heat colour of how many lights "
                 "each pixel with geometry sums (its tile's or cluster's list; every light for brute "
                 "force), on a log scale: black 0, blue 4, green 31, yellow 180, red 1023 or more.")
        .items(kShowItems, 2)
        .default_value(SHOW_LIGHT),
    param("nonfinite")
        .label("Non-finite input")
        .group("Input")
        .tooltip("How a NaN or infinite sample of the colour, emissive or albedo input is read, before "
                 "anything else. zero: every non-finite channel is 0; clamp: NaN is 0, +-Inf is +-65504 "
                 "(the largest half float). A non-finite normal lights nothing either way.")
        .items(kNonfiniteItems, 2)
        .default_value(NONFINITE_ZERO),
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
