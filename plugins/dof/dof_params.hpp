// The "dof" effect's parameters: indices into the descriptor table (and so into the value array the
// host passes), the enums' item indices, and the settings read out of the values once, so the GPU
// passes and the CPU references interpret them identically.
#pragma once

#include <cstdint>

#include <pfx/params.h>

namespace pfx_dof {

enum Param : uint32_t {
  PARAM_MODE,
  PARAM_FOCUS_DISTANCE,
  PARAM_AUTOFOCUS,
  PARAM_FOCUS_POINT,
  PARAM_F_NUMBER,
  PARAM_SENSOR_WIDTH,
  PARAM_MAX_COC,
  PARAM_SAMPLES,
  PARAM_RESOLUTION,
  PARAM_NONFINITE,
  PARAM_COUNT
};

enum Mode : int { MODE_SEED = 0, MODE_GATHER = 1 };
enum Autofocus : int { AUTOFOCUS_OFF = 0, AUTOFOCUS_POINT = 1 };
enum Resolution : int { RESOLUTION_HALF = 0, RESOLUTION_FULL = 1 };
// What a pixel holding NaN or +-Inf in R, G or B counts as, as the bloom plugin's parameter of the
// same name: zero: black, the whole pixel (a non-finite alpha 0 on its own); clamp: NaN -> 0 and
// +-Inf -> +-65504 channel by channel.
enum Nonfinite : int { NONFINITE_ZERO = 0, NONFINITE_CLAMP = 1 };

// Hard limits, shared by the descriptors and the tests that probe them.
constexpr double kMinFocusDistance = 0.001;  // m: 1 mm, closer than any lens focuses
constexpr double kMaxFocusDistance = 1e9;    // m: "infinity" (the CoC differs from a true infinity by < 1e-6 px)
constexpr double kMinFNumber = 0.05;         // a strong, unrealistic blur
constexpr double kMaxFNumber = 64;
constexpr double kMaxCocLimit = 128;         // px: dilation then spans at most 4 tiles each way
constexpr int kMinSamples = 8;
constexpr int kMaxSamples = 256;

extern const pfx_param_desc kParams[PARAM_COUNT];

struct Settings {
  int mode = MODE_GATHER;
  double focus_distance = 10.0;  // m
  int autofocus = AUTOFOCUS_OFF;
  double focus_point[2] = {0.5, 0.5};  // 0..1 across the frame, (0, 0) the top-left corner
  double f_number = 1.4;
  double sensor_width = 36.0;  // mm
  double max_coc = 32.0;       // px, a diameter at the frame's resolution
  int samples = 32;
  int resolution = RESOLUTION_HALF;
  int nonfinite = NONFINITE_ZERO;
};

Settings settings_from(const pfx_value* values);

}  // namespace pfx_dof
