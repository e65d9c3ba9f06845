// The "glare" effect's parameters (Kawase's star streaks) and the settings read out of them once,
// for the GPU passes and the CPU model alike. The bright pass is the bloom's, with the same
// threshold, knee, measure and firefly clamp parameters.
#pragma once

#include <cstdint>

#include <pfx/params.h>

#include "bloom_params.hpp"

namespace pfx_bloom {

enum GlareParam : uint32_t {
  GLARE_THRESHOLD,
  GLARE_KNEE,
  GLARE_MEASURE,
  GLARE_FIREFLY_CLAMP,
  GLARE_STRENGTH,
  GLARE_TINT,
  GLARE_STREAKS,
  GLARE_ANGLE,
  GLARE_ATTENUATION,
  GLARE_RESOLUTION,
  GLARE_NONFINITE,
  GLARE_PARAM_COUNT
};

// Kawase's cross filter: 3 passes of 16 taps per streak, tap s of pass i at b*s texels with b = 4^i.
constexpr int kGlarePasses = 3;
constexpr int kGlareTaps = 16;
constexpr int kMaxStreaks = 8;

extern const pfx_param_desc kGlareParams[GLARE_PARAM_COUNT];

struct GlareSettings {
  Settings bright;          // threshold, knee, measure, firefly_clamp, nonfinite (its other fields are unused)
  double strength = 1.0;
  double tint[3] = {1.0, 1.0, 1.0};
  int streaks = 4;          // 4, 6 or 8
  double angle = 0.785398163397448;  // radians, of the first streak
  double attenuation = 0.925;        // a
  int downscale = 1;        // 1, 2 or 4

  bool is_noop() const { return strength <= 0 || bright.firefly_clamp <= 0 || (tint[0] <= 0 && tint[1] <= 0 && tint[2] <= 0); }
  // The unit direction of streak j, in texels (x right, y up).
  void direction(int j, double* dx, double* dy) const;
  // The normalised weights a^(b*s) / sum of tap s = 0..15 of pass i (b = 4^i).
  void pass_weights(int pass, double* weights) const;
};

GlareSettings glare_settings_from(const pfx_value* values);

}  // namespace pfx_bloom
