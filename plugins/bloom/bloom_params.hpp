// The "bloom" effect's parameters: indices into the descriptor table (and so into the value
// array the host passes), the enums' item indices, and the settings read out of the values once,
// so the GPU passes and the CPU reference interpret them identically.
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
  PARAM_MEASURE,
  PARAM_FIREFLY_CLAMP,
  PARAM_TINT,
  PARAM_COUNT
};

enum Mode : int { MODE_CHAIN = 0 };
enum Measure : int { MEASURE_MAX_RGB = 0, MEASURE_LUMINANCE = 1 };

// The largest finite half float: no target may hold more.
constexpr double kHalfMax = 65504.0;
// Every level of the pyramid holds at most this divided by the level count, so the levels summed
// on the way up (each store rounding up by at most half a half-float ulp) stay below 65520, where
// half floats overflow to infinity.
constexpr double kLevelSumMax = 65000.0;
// Below this a brightness counts as zero (the seed's guard against dividing by zero).
constexpr double kBrightnessFloor = 1e-5;

extern const pfx_param_desc kParams[PARAM_COUNT];

struct Settings {
  int mode = MODE_CHAIN;
  double threshold = 1.0;
  double knee = 0.0;  // already limited to the threshold (see settings_from)
  double strength = 1.0;
  int levels = 0;     // as asked: 0 = automatic
  int auto_min_size = 16;
  int measure = MEASURE_MAX_RGB;
  double firefly_clamp = 65472.0;
  double tint[3] = {1.0, 1.0, 1.0};

  // Strength 0, a black tint or a zero clamp add nothing: the effect then declares no pass.
  bool is_noop() const;
};

Settings settings_from(const pfx_value* values);

}  // namespace pfx_bloom
