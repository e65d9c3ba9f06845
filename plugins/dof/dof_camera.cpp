#include "dof_camera.hpp"

#include <algorithm>
#include <cmath>

#include <pfx/depth.h>

namespace pfx_dof {

double horizontal_fov(double fovy, double aspect) { return 2.0 * std::atan(std::tan(0.5 * fovy) * aspect); }

std::string camera_problem(const pfx_frame& frame) {
  const pfx_camera& c = frame.camera;
  if (!(c.fovy > 0.0f) || !(c.fovy < static_cast<float>(M_PI)))
    return "the frame's vertical field of view is " + std::to_string(c.fovy) +
           " rad; depth of field needs 0 < fovy < pi";
  if (!(c.aspect > 0.0f) || !std::isfinite(c.aspect))
    return "the frame's aspect ratio is " + std::to_string(c.aspect) + "; depth of field needs a positive aspect";
  if (frame.depth_encoding != PFX_DEPTH_LINEAR) {
    if (!(c.near_plane > 0.0f) || !std::isfinite(c.near_plane))
      return "the frame's near plane is " + std::to_string(c.near_plane) +
             " m; decoding hardware depth needs a positive, finite near plane";
    if (!(c.far_plane >= c.near_plane))
      return "the frame's far plane (" + std::to_string(c.far_plane) + " m) is nearer than its near plane (" +
             std::to_string(c.near_plane) + " m)";
  }
  return "";
}

Lens make_lens(const pfx_frame& frame, const Settings& s, double focus_distance_m) {
  Lens lens;
  if (std::isnan(focus_distance_m)) focus_distance_m = s.focus_distance;
  const double p = std::clamp(focus_distance_m, kMinFocusDistance, kMaxFocusDistance);
  const double fovx = horizontal_fov(frame.camera.fovy, frame.camera.aspect);
  const double i = 0.5 * s.sensor_width / std::tan(0.5 * fovx);
  const double p_mm = 1000.0 * p;
  lens.image_distance_mm = i;
  lens.focus_distance_m = p;
  lens.focal_length_mm = 1.0 / (1.0 / p_mm + 1.0 / i);
  lens.aperture_mm = lens.focal_length_mm / s.f_number;
  lens.px_per_mm = double(frame.width) / s.sensor_width;
  lens.inverse_focus = 1.0 / p;
  // I^2 (1/P - 1/D) / (N (1 + I/P)) mm with P, D in mm is C (1/P - 1/D) with them in metres.
  lens.coc_scale = i * i * lens.px_per_mm / (s.f_number * (1000.0 + i * lens.inverse_focus));
  lens.max_coc = s.max_coc;
  return lens;
}

double coc_pixels(const Lens& lens, double view_depth_m) {
  if (std::isnan(view_depth_m)) return 0.0;
  if (view_depth_m <= 0.0) return -lens.max_coc;
  const double coc = lens.coc_scale * (lens.inverse_focus - 1.0 / view_depth_m);  // 1/inf = 0
  return std::clamp(coc, -lens.max_coc, lens.max_coc);
}

void focus_texel(uint32_t width, uint32_t height, const Settings& s, uint32_t* x, uint32_t* y) {
  const double fx = std::floor(s.focus_point[0] * width), fy = std::floor(s.focus_point[1] * height);
  *x = static_cast<uint32_t>(std::clamp(fx, 0.0, width - 1.0));
  const uint32_t row_from_top = static_cast<uint32_t>(std::clamp(fy, 0.0, height - 1.0));
  *y = height - 1 - row_from_top;
}

double view_depth(const pfx_frame& frame, double stored) {
  return pfx_view_depth(stored, frame.depth_encoding, frame.camera.near_plane, frame.camera.far_plane);
}

double focus_distance(const pfx_frame& frame, const Settings& s, const float* depth) {
  if (s.autofocus != AUTOFOCUS_POINT || !depth) return s.focus_distance;
  uint32_t x = 0, y = 0;
  focus_texel(frame.width, frame.height, s, &x, &y);
  const double d = view_depth(frame, depth[static_cast<size_t>(y) * frame.width + x]);
  if (std::isnan(d)) return s.focus_distance;
  return std::clamp(d, kMinFocusDistance, kMaxFocusDistance);
}

}  // namespace pfx_dof
