// What every CPU reference of "dof" reads first, exactly as the GPU passes read it: the colour made
// safe (nonfinite zero: a pixel with NaN or +-Inf in R, G or B black, a non-finite alpha 0; clamp:
// NaN -> 0 per channel; both: magnitudes clamped to the largest half float),
// the lens (with autofocus resolved against the depth), and each pixel's signed CoC.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <pfx/effect.h>

#include "dof_camera.hpp"
#include "dof_params.hpp"
#include "reference/dof_image.hpp"

namespace pfx_dof {

constexpr double kHalfMax = 65504.0;

inline double safe_value(double v) { return std::isnan(v) ? 0.0 : std::clamp(v, -kHalfMax, kHalfMax); }

// How much of a pixel at distance d from a disc's centre a disc of radius r covers: a one-pixel
// ramp across the rim, as the scatter reference and the gather model both draw a disc.
inline double disc_coverage(double d, double r) { return std::clamp(r - d + 0.5, 0.0, 1.0); }

// color: width * height RGBA, rows bottom first; nonfinite: Nonfinite (dof_params.hpp).
Texture safe_color(const pfx_frame& frame, const float* color, int nonfinite);

// The lens the passes use for this frame (autofocus read from depth).
Lens frame_lens(const pfx_frame& frame, const Settings& settings, const float* depth);

// Signed CoC diameter in pixels per pixel, rows bottom first.
std::vector<double> coc_image(const pfx_frame& frame, const Lens& lens, const float* depth);

}  // namespace pfx_dof
