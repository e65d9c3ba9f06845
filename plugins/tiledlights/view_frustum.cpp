#include "view_frustum.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pfx_tiledlights {

bool perspective_of(const pfx_camera& camera, Perspective* out, std::string* error) {
  const float* p = camera.projection;
  // Column-major: w_clip = P[3] x + P[7] y + P[11] z + P[15]; a perspective has w = -z.
  if (p[3] != 0 || p[7] != 0 || p[11] != -1 || p[15] != 0 || p[1] != 0 || p[4] != 0 || !(p[0] > 0) ||
      !(p[5] > 0) || !std::isfinite(p[0]) || !std::isfinite(p[5]) || !std::isfinite(p[8]) || !std::isfinite(p[9])) {
    *error = "the camera's projection is not a perspective projection (w_clip must be -z_view, no skew)";
    return false;
  }
  out->scale_x = p[0];
  out->scale_y = p[5];
  out->offset_x = p[8];
  out->offset_y = p[9];
  return true;
}

SidePlanes side_planes(const Perspective& perspective, int width, int height, double x0, double x1, double y0,
                       double y1) {
  // The ray slopes at the rectangle's edges: x_view / depth = a, y_view / depth = b.
  const double a0 = (2 * x0 / width - 1 + perspective.offset_x) / perspective.scale_x;
  const double a1 = (2 * x1 / width - 1 + perspective.offset_x) / perspective.scale_x;
  const double b0 = (2 * y0 / height - 1 + perspective.offset_y) / perspective.scale_y;
  const double b1 = (2 * y1 / height - 1 + perspective.offset_y) / perspective.scale_y;
  // With depth = -z: inside the left plane is x >= a0 * depth, i.e. x + a0 z >= 0.
  SidePlanes planes;
  auto set = [&](int i, double x, double y, double z) {
    const double length = std::sqrt(x * x + y * y + z * z);
    planes.n[i][0] = x / length;
    planes.n[i][1] = y / length;
    planes.n[i][2] = z / length;
  };
  set(0, 1, 0, a0);    // left
  set(1, -1, 0, -a1);  // right
  set(2, 0, 1, b0);    // bottom
  set(3, 0, -1, -b1);  // top
  return planes;
}

bool sphere_touches(const SidePlanes& planes, const double centre[3], double radius) {
  for (const auto& n : planes.n)
    if (n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] < -radius) return false;
  return true;
}

bool invert_matrix(const double m[16], double out[16]) {
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a[r][c] = m[c * 4 + r];
      a[r][c + 4] = r == c ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (a[pivot][c] == 0) return false;
    std::swap(a[c], a[pivot]);
    const double inv = 1.0 / a[c][c];
    for (double& v : a[c]) v *= inv;
    for (int r = 0; r < 4; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
      }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[c * 4 + r] = a[r][c + 4];
  return true;
}

}  // namespace pfx_tiledlights
