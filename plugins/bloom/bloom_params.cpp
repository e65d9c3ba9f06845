#include "bloom_params.hpp"

#include <algorithm>

#include "bloom_levels.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_bloom {
namespace {

const pfx_enum_item kModeItems[] = {
    {"chain", "Seed chain: 5-tap bright pass, 8x8 downsample, 3x3 tent upsample"}};

const pfx_enum_item kMeasureItems[] = {
    {"max_rgb", "Largest of R, G, B (the seed's)"},
    {"luminance", "Rec. 709 luminance"}};

}  // namespace

// Hard ranges are finite so "inf" from a user clamps to something the shaders can use. Threshold
// and knee stop at the half-float maximum: no stored colour is brighter than that.
const pfx_param_desc kParams[PARAM_COUNT] = {
    pfx::desc::with_items(pfx::desc::param("mode", "Mode",
                    "Which bloom algorithm runs. chain: the seed's pyramid (bright pass into half size, "
                    "8x8 blurred downsamples, 3x3 tent upsamples added back up).",
                    "", "Bloom", PFX_PARAM_ENUM, 0, 0, 0, 0, 1, {{MODE_CHAIN}}),
               kModeItems, 1),
    pfx::desc::param("threshold", "Threshold",
         "Brightness above which light blooms. Scene-linear: 1 is the brightness of diffuse white.",
         "", "Bright pass", PFX_PARAM_FLOAT, 0, kHalfMax, 0, 8, 0.05, {{1.0}}),
    pfx::desc::param("knee", "Knee",
         "Width of the soft transition around the threshold: brightness from threshold - knee to "
         "threshold + knee blooms gradually (quadratic). 0 is the seed's hard threshold; the knee is "
         "never wider than the threshold.",
         "", "Bright pass", PFX_PARAM_FLOAT, 0, kHalfMax, 0, 2, 0.05, {{0.0}}),
    pfx::desc::param("strength", "Strength",
         "How much light the bloom adds: 1 spreads exactly the light above the threshold. Divided among "
         "the levels, as in the seed. 0 turns the effect off (no pass runs).",
         "", "Bloom", PFX_PARAM_FLOAT, 0, 100, 0, 4, 0.05, {{1.0}}),
    pfx::desc::param("levels", "Levels",
         "Number of half-size pyramid levels; more levels spread the light further. 0 chooses "
         "automatically from the frame size (see Automatic minimum size). Clamped to what the frame allows.",
         "", "Bloom", PFX_PARAM_INT, 0, kMaxLevels, 0, 10, 1, {{0}}),
    pfx::desc::param("auto_min_size", "Automatic minimum size",
         "With levels 0, no level is added whose shorter side would be below this many pixels "
         "(16 gives the seed's 6 levels at 1920x1080).",
         "px", "Bloom", PFX_PARAM_INT, 1, 4096, 1, 64, 1, {{16}}),
    pfx::desc::with_items(pfx::desc::param("measure", "Brightness measure",
                    "How a pixel's brightness is measured against the threshold: the largest of R, G, B "
                    "(the seed's; saturated blue blooms like white) or Rec. 709 luminance.",
                    "", "Bright pass", PFX_PARAM_ENUM, 0, 1, 0, 1, 1, {{MEASURE_MAX_RGB}}),
               kMeasureItems, 2),
    pfx::desc::param("firefly_clamp", "Firefly clamp",
         "Every colour channel is clamped to this before the bright pass, so single very bright (or "
         "infinite) pixels cannot dominate the bloom. Not-a-number pixels count as black.",
         "", "Bright pass", PFX_PARAM_FLOAT, 0, kHalfMax, 1, kHalfMax, 1, {{65472.0}}),
    pfx::desc::param("tint", "Tint", "Colour the added light is multiplied by.", "", "Bloom", PFX_PARAM_COLOR, 0, 16, 0, 1,
         0.01, {{1.0, 1.0, 1.0}}),
};

bool Settings::is_noop() const {
  return strength <= 0 || firefly_clamp <= 0 || (tint[0] <= 0 && tint[1] <= 0 && tint[2] <= 0);
}

Settings settings_from(const pfx_value* values) {
  Settings s;
  s.mode = static_cast<int>(values[PARAM_MODE].v[0]);
  s.threshold = values[PARAM_THRESHOLD].v[0];
  // A knee wider than the threshold would give black pixels a non-zero bright part, and more light
  // out than in; limiting it keeps the bright part between 0 and the colour.
  s.knee = std::min(values[PARAM_KNEE].v[0], s.threshold);
  s.strength = values[PARAM_STRENGTH].v[0];
  s.levels = static_cast<int>(values[PARAM_LEVELS].v[0]);
  s.auto_min_size = static_cast<int>(values[PARAM_AUTO_MIN_SIZE].v[0]);
  s.measure = static_cast<int>(values[PARAM_MEASURE].v[0]);
  s.firefly_clamp = values[PARAM_FIREFLY_CLAMP].v[0];
  for (int c = 0; c < 3; ++c) s.tint[c] = values[PARAM_TINT].v[c];
  return s;
}

}  // namespace pfx_bloom
