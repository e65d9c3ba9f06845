#include "bloom_params.hpp"

#include <algorithm>

#include "bloom_levels.hpp"
#include "bright_pass_params.hpp"

#include <pfx/cpp/descriptors.hpp>

namespace pfx_bloom {
namespace {

const pfx_enum_item kModeItems[MODE_COUNT] = {
    {"chain", "Half-size pyramid: 5-tap bright pass, 8x8 downsample, 3x3 tent upsample"},
    {"chain13", "13-tap chain: 13-tap downsample, Karis average on the first level"},
    {"gaussian", "Separable Gaussian at a chosen downscale"},
    {"mgf", "Kawase multi-Gaussian: Gaussians on 1/4, 1/8 ... buffers, summed"}};

}  // namespace

const char* mode_name(int mode) { return mode >= 0 && mode < MODE_COUNT ? kModeItems[mode].id : "?"; }

// Hard ranges are finite so "inf" from a user clamps to something the shaders can use.
const pfx_param_desc kParams[PARAM_COUNT] = {
    pfx::desc::param("mode")
        .label("Mode")
        .group("Bloom")
        .tooltip("Which bloom algorithm runs. chain: a half-size pyramid (Call of Duty: Advanced Warfare "
                 "style); chain13: the same with the 13-tap downsample and a Karis average against fireflies; "
                 "gaussian: one separable Gaussian at a downscale; mgf: Kawase's sum of Gaussians on 1/4, "
                 "1/8 ... buffers.")
        .items(kModeItems, MODE_COUNT)
        .default_value(MODE_CHAIN),
    // On a display-referred frame: 0.6 is linear light of sRGB code 204 (80 % grey); the knee
    // eases in from 0.4 (code 170), so the top of the range glows while mid-tones stay.
    threshold_param(0.6),
    knee_param(0.2),
    pfx::desc::param("strength")
        .label("Strength")
        .group("Bloom")
        .tooltip("How much light the bloom adds: 1 spreads exactly the light above the threshold. 0 adds "
                 "nothing (no pass runs, unless the gaussian mode's tone scale is not 1).")
        .float_range(0, 100)
        .display_range(0, 4)
        .step(0.05)
        .default_value(1.0),
    pfx::desc::param("levels")
        .label("Levels")
        .group("Bloom")
        .tooltip("Pyramid levels (chain, chain13) or Gaussian buffers (mgf); more spread the light further. "
                 "0 chooses automatically (see the two automatic limits). Clamped to what the frame allows.")
        .int_range(0, kMaxLevels)
        .display_range(0, 10)
        .default_value(0),
    pfx::desc::param("auto_min_size")
        .label("Automatic minimum size")
        .unit("px")
        .group("Bloom")
        .tooltip("With levels 0, no level is added whose shorter side would be below this many pixels "
                 "(16 gives 6 levels at 1920x1080).")
        .int_range(1, 4096)
        .display_range(1, 64)
        .default_value(16),
    pfx::desc::param("auto_min_share")
        .label("Automatic minimum share")
        .group("Bloom")
        .tooltip("With levels 0, no level is added that would carry less than this fraction of the bloom's "
                 "light. Chain levels each carry 1/levels; mgf buffers follow the mgf ratio. 0 turns this off.")
        .float_range(0, 1)
        .display_range(0, 0.2)
        .step(0.005)
        .default_value(0.0),
    measure_param("How a pixel's brightness is measured against the threshold: the largest of R, G, B "
                  "(saturated blue blooms like white) or Rec. 709 luminance. The gaussian mode thresholds "
                  "each channel on its own and ignores this."),
    firefly_clamp_param(),
    pfx::desc::param("tint")
        .label("Tint")
        .group("Bloom")
        .tooltip("Colour the added light is multiplied by.")
        .color_range(0, 16)
        .display_range(0, 1)
        .step(0.01)
        .default_value(1.0, 1.0, 1.0),
    pfx::desc::param("sigma")
        .label("Sigma")
        .unit("px")
        .group("Gaussian")
        .tooltip("gaussian mode: the Gaussian's standard deviation, in pixels of the frame (whatever the "
                 "downscale). The bloom's radius grows with it; so must the tap count.")
        .float_range(0.1, 4000)
        .display_range(1, 200)
        .step(0.5)
        .default_value(8.0),
    pfx::desc::param("taps")
        .label("Taps")
        .group("Gaussian")
        .tooltip("gaussian mode: taps of each 1-D blur, one texel of the downscaled buffer apart (15 by "
                 "default). An even count is rounded up to the next odd one. To cover the Gaussian, taps x "
                 "downscale should reach about 6 sigma.")
        .int_range(1, 2 * kMaxHalfTaps + 1)
        .display_range(1, 63)
        .step(2)
        .default_value(15),
    pfx::desc::param("downscale")
        .label("Downscale")
        .group("Gaussian")
        .tooltip("gaussian mode: the blur runs on a buffer this many times smaller than the frame on each "
                 "side (each texel the average of downscale x downscale pixels); 1 blurs at full resolution.")
        .int_range(1, 16)
        .display_range(1, 8)
        .default_value(4),
    pfx::desc::param("tone_scale")
        .label("Tone scale")
        .group("Gaussian")
        .tooltip("gaussian mode: the frame is multiplied by this before the bloom is added (0.7 darkens "
                 "the frame as a tone scale would). 1 keeps the frame as it is.")
        .float_range(0, 16)
        .display_range(0, 1)
        .step(0.05)
        .default_value(1.0),
    pfx::desc::param("mgf_ratio")
        .label("Multi-Gaussian ratio")
        .group("Multi-Gaussian")
        .tooltip("mgf mode: each coarser buffer's Gaussian carries this many times the light of the finer one "
                 "(Kawase's kernel e^-(0.25r)^2 + 2e^-(0.5r)^2 + 4e^-r^2 ...: 2). The weights are normalised "
                 "so all buffers together carry strength x the light above the threshold.")
        .float_range(0.1, 10)
        .display_range(0.5, 4)
        .step(0.1)
        .default_value(2.0),
    nonfinite_param(),
    pfx::desc::param("karis")
        .label("Karis average")
        .group("Bright pass")
        .tooltip("chain and mgf: weight every tap of the first downsample by 1 / (1 + its luminance) (Karis), as "
                 "chain13 does, so a lone very bright pixel (a firefly) cannot outshine its neighbours. Takes "
                 "light from small bright details; off keeps plain averages.")
        .boolean()
        .default_value(0.0),
};

bool Settings::adds_nothing() const {
  return strength <= 0 || firefly_clamp <= 0 || (tint[0] <= 0 && tint[1] <= 0 && tint[2] <= 0);
}

bool Settings::is_noop() const { return adds_nothing() && (mode != MODE_GAUSSIAN || tone_scale == 1.0); }

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
  s.auto_min_share = values[PARAM_AUTO_MIN_SHARE].v[0];
  s.measure = static_cast<int>(values[PARAM_MEASURE].v[0]);
  s.firefly_clamp = values[PARAM_FIREFLY_CLAMP].v[0];
  for (int c = 0; c < 3; ++c) s.tint[c] = values[PARAM_TINT].v[c];
  s.sigma = values[PARAM_SIGMA].v[0];
  s.half_taps = std::min(static_cast<int>(values[PARAM_TAPS].v[0]) / 2, kMaxHalfTaps);
  s.downscale = static_cast<int>(values[PARAM_DOWNSCALE].v[0]);
  s.tone_scale = values[PARAM_TONE_SCALE].v[0];
  s.mgf_ratio = values[PARAM_MGF_RATIO].v[0];
  s.nonfinite = static_cast<int>(values[PARAM_NONFINITE].v[0]);
  s.karis = values[PARAM_KARIS].v[0] != 0;
  return s;
}

}  // namespace pfx_bloom
