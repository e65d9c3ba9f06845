// The "bloom" effect's parameters: indices into the descriptor table (and so into the value
// array the host passes), the enums' item indices, and the settings read out of the values once,
// so the GPU passes and the CPU references interpret them identically.
#pragma once

#include <cstdint>

#include <pfx/params.h>

namespace pfx_bloom {

enum Param : uint32_t {
  PARAM_MODE,
  PARAM_THRESHOLD,
  PARAM_KNEE,
  PARAM_STRENGTH,
  PARAM_LEVELS,
  PARAM_AUTO_MIN_SIZE,
  PARAM_AUTO_MIN_SHARE,
  PARAM_MEASURE,
  PARAM_FIREFLY_CLAMP,
  PARAM_TINT,
  PARAM_SIGMA,
  PARAM_TAPS,
  PARAM_DOWNSCALE,
  PARAM_TONE_SCALE,
  PARAM_MGF_RATIO,
  PARAM_NONFINITE,
  PARAM_KARIS,
  PARAM_COUNT
};

enum Mode : int { MODE_CHAIN = 0, MODE_CHAIN13 = 1, MODE_GAUSSIAN = 2, MODE_MGF = 3, MODE_COUNT = 4 };
enum Measure : int { MEASURE_MAX_RGB = 0, MEASURE_LUMINANCE = 1 };
// What a pixel holding NaN or +-Inf in R, G or B counts as, before any filtering. zero: black, the
// whole pixel (a renderer's failed sample carries no light; its alpha, if not finite, becomes 0 on
// its own). clamp: NaN -> 0 and +-Inf -> +-65504 per channel, so +Inf blooms as the firefly clamp.
enum Nonfinite : int { NONFINITE_ZERO = 0, NONFINITE_CLAMP = 1 };

// The mode names, as the enum items spell them (for messages and reports).
const char* mode_name(int mode);

// The largest finite half float: no target may hold more.
constexpr double kHalfMax = 65504.0;
// Every level of the pyramid holds at most this divided by the level count, so the levels summed
// on the way up (each store rounding up by at most half a half-float ulp) stay below 65520, where
// half floats overflow to infinity.
constexpr double kLevelSumMax = 65000.0;
// Below this a brightness counts as zero (a guard against dividing by zero).
constexpr double kBrightnessFloor = 1e-5;
// Kawase's multi-Gaussian: a Gaussian of this deviation, in texels of each buffer, with
// this many taps (Kawase's: the centre and 7 on each side).
constexpr double kMgfDeviation = 2.5;
constexpr int kMgfTaps = 15;
// The widest separable Gaussian the shaders take (taps on one side of the centre).
constexpr int kMaxHalfTaps = 511;

extern const pfx_param_desc kParams[PARAM_COUNT];

struct Settings {
  int mode = MODE_CHAIN;
  double threshold = 1.0;
  double knee = 0.0;  // already limited to the threshold (see settings_from)
  double strength = 1.0;
  int levels = 0;     // as asked: 0 = automatic
  int auto_min_size = 16;
  double auto_min_share = 0.0;
  int measure = MEASURE_MAX_RGB;
  double firefly_clamp = 65472.0;
  double tint[3] = {1.0, 1.0, 1.0};
  double sigma = 8.0;      // gaussian: px of the frame
  int half_taps = 7;       // gaussian: taps on each side of the centre (taps = 2 * half_taps + 1)
  int downscale = 4;       // gaussian
  double tone_scale = 1.0; // gaussian
  double mgf_ratio = 2.0;  // mgf: each coarser buffer's light over the finer one's
  int nonfinite = NONFINITE_ZERO;
  bool karis = false;      // chain, mgf: the first downsample Karis-weighted (chain13 always is)

  // Strength 0, a black tint or a zero clamp: no light is added.
  bool adds_nothing() const;
  // Nothing is added and the frame is not scaled either: the effect then declares no pass.
  bool is_noop() const;
};

Settings settings_from(const pfx_value* values);

}  // namespace pfx_bloom
