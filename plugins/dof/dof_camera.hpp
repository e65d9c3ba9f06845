// The thin-lens camera shared by every mode and by the CPU references: the thin-lens circle of
// confusion, with the horizontal field of view computed exactly.
//
// The sensor sits at the image distance I that reproduces the frame's horizontal field of view on a
// sensor of the given width; the lens focuses a plane at distance P, so its focal length is
// F = 1 / (1/P + 1/I) and its aperture A = F / N. A point at view depth D then blurs into a circle
// of diameter (on the sensor, in mm)
//
//   CoC = A F (D - P) / (D (P - F))               (the textbook thin-lens formula, signed: near negative)
//       = I^2 (1/P - 1/D) / (N (1 + I/P))         (substituting F and A; all in mm)
//
// and in pixels CoC * width / sensor width. The second form has no P - F denominator (P == F is the
// first form's division by zero) and stays finite for P or D at infinity, so it is what everything here
// evaluates: CoC_px = C * (1/P - 1/D) with D and P in metres and C from the camera and lens.
#pragma once

#include <string>

#include <pfx/effect.h>

#include "dof_params.hpp"

namespace pfx_dof {

// The true horizontal field of view of a perspective camera: 2 atan(tan(fovy / 2) aspect). (Not
// fovy * aspect, which is only close for narrow angles.)
double horizontal_fov(double fovy, double aspect);

// Empty when the frame's camera can drive the lens model, else why not (a degenerate field of view,
// aspect or near plane), worded for the host log.
std::string camera_problem(const pfx_frame& frame);

struct Lens {
  double image_distance_mm = 0;  // I
  double focus_distance_m = 0;   // P, in [kMinFocusDistance, kMaxFocusDistance]
  double focal_length_mm = 0;    // F = 1 / (1/P + 1/I)
  double aperture_mm = 0;        // A = F / N
  double px_per_mm = 0;          // frame width / sensor width
  double coc_scale = 0;          // C: CoC in px = C * (1/P - 1/D), D and P in metres
  double inverse_focus = 0;      // 1/P, in 1/m
  double max_coc = 0;            // px: |CoC| is clamped to this
};

// The lens for a frame (whose camera_problem() is empty), the settings, and a focus distance in
// metres (clamped to the focus distance's hard range; NaN counts as the settings' distance).
Lens make_lens(const pfx_frame& frame, const Settings& settings, double focus_distance_m);

// Signed CoC diameter in pixels at the frame's resolution for a linear view depth in metres,
// clamped to +-max_coc. Depth +inf (sky) gives the far limit C/P; depth <= 0 is nearer than any
// lens can see and gives -max_coc; NaN gives 0 (the pixel is left sharp and spreads nowhere).
double coc_pixels(const Lens& lens, double view_depth_m);

// The focus distance the passes use: the settings' distance, or with autofocus the view depth of
// the depth texel under the focus point (rows bottom first, as GL textures; 0.5 picks the texel
// right of and below the centre on even sizes). The sky (+inf) focuses at infinity (the hard
// maximum); a depth that cannot be decoded (NaN) falls back to the settings' distance.
double focus_distance(const pfx_frame& frame, const Settings& settings, const float* depth);

// The depth texel autofocus reads, (x, y) with y counted from the bottom row.
void focus_texel(uint32_t width, uint32_t height, const Settings& settings, uint32_t* x, uint32_t* y);

// A stored depth value as linear view depth in metres (pfx/depth.h), for the frame's encoding.
double view_depth(const pfx_frame& frame, double stored);

}  // namespace pfx_dof
