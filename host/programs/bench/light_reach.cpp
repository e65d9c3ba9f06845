#include "light_reach.hpp"

#include <algorithm>
#include <cmath>

#include <pfx/depth.h>

namespace pfx::bench {
namespace {

struct Light {
  double p[3];  // view space
  double range2;
  bool radiant;  // some colour channel times intensity is > 0
};

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void cross(const double a[3], const double b[3], double out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// A pixel's view-space point; geometry: its view depth is positive and finite.
struct Point {
  double p[3];
  bool geometry;
};

// Whether the light's range reaches p, with the vector from p to the light in to_light.
bool reaches(const Light& l, const double p[3], double to_light[3]) {
  for (int k = 0; k < 3; ++k) to_light[k] = l.p[k] - p[k];
  return dot(to_light, to_light) < l.range2;
}

// The lights in view space (the view matrix is column-major), with their ranges squared; a light
// without a range (none given, and too faint to reach the cutoff) is left out.
std::vector<Light> view_lights(const pfx_frame& frame, double cutoff) {
  std::vector<Light> lights;
  const auto* bytes = reinterpret_cast<const unsigned char*>(frame.lights);
  const float* v = frame.camera.view;
  for (uint32_t i = 0; i < frame.light_count; ++i) {
    const pfx_light& l = *reinterpret_cast<const pfx_light*>(bytes + size_t(i) * frame.light_struct_size);
    const double peak = double(l.intensity) * std::fmax(l.color[0], std::fmax(l.color[1], l.color[2]));
    double range = l.range;
    if (!(range > 0)) range = peak > cutoff ? std::sqrt(peak / cutoff - 1) : 0;
    if (!(range > 0)) continue;
    const double p[3] = {l.position[0], l.position[1], l.position[2]};
    lights.push_back({{v[0] * p[0] + v[4] * p[1] + v[8] * p[2] + v[12], v[1] * p[0] + v[5] * p[1] + v[9] * p[2] + v[13],
                       v[2] * p[0] + v[6] * p[1] + v[10] * p[2] + v[14]},
                      range * range,
                      peak > 0});
  }
  return lights;
}

// Takes world-space normals to view space up to a positive factor, which keeps N.L's sign: with M
// the view's rotation part, n_w . l_w = (M^-T n_w) . l_v, and M^-T's rows are the cross products of
// M's rows over det(M).
class NormalToView {
 public:
  explicit NormalToView(const float* v) {
    const double rows[3][3] = {{v[0], v[4], v[8]}, {v[1], v[5], v[9]}, {v[2], v[6], v[10]}};
    cross(rows[1], rows[2], to_view_[0]);
    cross(rows[2], rows[0], to_view_[1]);
    cross(rows[0], rows[1], to_view_[2]);
    det_sign_ = dot(rows[0], to_view_[0]) < 0 ? -1.0 : 1.0;
  }
  void apply(const double nw[3], double n[3]) const {
    for (int k = 0; k < 3; ++k) n[k] = det_sign_ * dot(to_view_[k], nw);
  }

 private:
  double to_view_[3][3];
  double det_sign_;
};

// Each pixel's view-space point, as tiledlights reconstructs it (w_clip = -z_view).
std::vector<Point> view_points(const pfx_frame& frame, const std::vector<float>& depth) {
  const float* P = frame.camera.projection;
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  std::vector<Point> points(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Point& point = points[size_t(y) * w + x];
      const double d = pfx_view_depth(depth[size_t(y) * w + x], frame.depth_encoding, frame.camera.near_plane,
                                      frame.camera.far_plane);
      point.geometry = d > 0 && std::isfinite(d);
      point.p[0] = d * (2.0 * (x + 0.5) / w - 1 + P[8]) / P[0];
      point.p[1] = d * (2.0 * (y + 0.5) / h - 1 + P[9]) / P[5];
      point.p[2] = -d;
    }
  return points;
}

// Per tile: the lights reaching any of its points, summed once for each of its pixels with geometry.
double tile_reaching_sum(const std::vector<Point>& points, const std::vector<Light>& lights, int w, int h, int tile) {
  double sum = 0;
  for (int ty = 0; ty < h; ty += tile)
    for (int tx = 0; tx < w; tx += tile) {
      std::vector<const Point*> tile_points;
      for (int y = ty; y < std::min(ty + tile, h); ++y)
        for (int x = tx; x < std::min(tx + tile, w); ++x)
          if (points[size_t(y) * w + x].geometry) tile_points.push_back(&points[size_t(y) * w + x]);
      uint64_t count = 0;
      for (const Light& l : lights)
        for (const Point* point : tile_points) {
          double to_light[3];
          if (reaches(l, point->p, to_light)) {
            ++count;
            break;
          }
        }
      sum += double(count) * double(tile_points.size());
    }
  return sum;
}

}  // namespace

LightReach count_light_reach(const pfx_frame& frame, const std::vector<float>& depth, const std::vector<float>& normal,
                             double cutoff, int tile) {
  const std::vector<Light> lights = view_lights(frame, cutoff);
  const NormalToView to_view(frame.camera.view);
  const std::vector<Point> points = view_points(frame, depth);

  LightReach out;
  double reaching = 0, lit = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].geometry) continue;
    // A normal with a non-finite component faces nothing, as in the shading pass.
    double nw[3] = {normal[i * 4], normal[i * 4 + 1], normal[i * 4 + 2]};
    if (!std::isfinite(nw[0]) || !std::isfinite(nw[1]) || !std::isfinite(nw[2])) nw[0] = nw[1] = nw[2] = 0;
    double n[3];
    to_view.apply(nw, n);
    for (const Light& l : lights) {
      double to_light[3];
      if (!reaches(l, points[i].p, to_light)) continue;
      reaching += 1;
      lit += l.radiant && (dot(to_light, to_light) == 0 || dot(n, to_light) > 0);
    }
    ++out.pixels;
  }
  const double tile_reaching = tile_reaching_sum(points, lights, static_cast<int>(frame.width),
                                                 static_cast<int>(frame.height), tile);
  if (out.pixels) {
    out.reaching_mean = reaching / double(out.pixels);
    out.lit_mean = lit / double(out.pixels);
    out.tile_reaching_mean = tile_reaching / double(out.pixels);
  }
  return out;
}

}  // namespace pfx::bench
