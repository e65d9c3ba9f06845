#include "light_reach.hpp"

#include <cmath>
#include <cstdint>

#include <pfx/depth.h>

namespace pfx::bench {

double mean_lights_reaching(const pfx_frame& frame, const std::vector<float>& depth, double cutoff) {
  // The lights in view space (the view matrix is column-major), with their ranges squared.
  struct Light {
    double x, y, z, range2;
  };
  std::vector<Light> lights;
  const auto* bytes = reinterpret_cast<const unsigned char*>(frame.lights);
  const float* v = frame.camera.view;
  for (uint32_t i = 0; i < frame.light_count; ++i) {
    const pfx_light& l = *reinterpret_cast<const pfx_light*>(bytes + size_t(i) * frame.light_struct_size);
    double range = l.range;
    if (!(range > 0)) {
      const double peak = double(l.intensity) * std::fmax(l.color[0], std::fmax(l.color[1], l.color[2]));
      range = peak > cutoff ? std::sqrt(peak / cutoff - 1) : 0;
    }
    if (!(range > 0)) continue;
    const double p[3] = {l.position[0], l.position[1], l.position[2]};
    lights.push_back({v[0] * p[0] + v[4] * p[1] + v[8] * p[2] + v[12], v[1] * p[0] + v[5] * p[1] + v[9] * p[2] + v[13],
                      v[2] * p[0] + v[6] * p[1] + v[10] * p[2] + v[14], range * range});
  }
  // A pixel's view-space point, as tiledlights reconstructs it (w_clip = -z_view).
  const float* P = frame.camera.projection;
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  double reached = 0;
  uint64_t pixels = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = pfx_view_depth(depth[size_t(y) * w + x], frame.depth_encoding, frame.camera.near_plane,
                                      frame.camera.far_plane);
      if (!(d > 0) || !std::isfinite(d)) continue;
      const double px = d * (2.0 * (x + 0.5) / w - 1 + P[8]) / P[0], py = d * (2.0 * (y + 0.5) / h - 1 + P[9]) / P[5];
      const double pz = -d;
      uint64_t count = 0;
      for (const Light& l : lights) {
        const double dx = l.x - px, dy = l.y - py, dz = l.z - pz;
        count += dx * dx + dy * dy + dz * dz < l.range2;
      }
      reached += double(count);
      ++pixels;
    }
  return pixels ? reached / double(pixels) : 0.0;
}

}  // namespace pfx::bench
