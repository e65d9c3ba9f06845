#include "obj_triangulate.hpp"

#include <algorithm>
#include <cmath>

namespace pfx_obj {

namespace {

void fan(uint32_t first, const std::vector<uint32_t>& next, uint32_t remaining, std::vector<uint32_t>* triangles) {
  uint32_t a = next[first];
  for (uint32_t k = 0; k + 2 < remaining; ++k) {
    uint32_t b = next[a];
    triangles->insert(triangles->end(), {first, a, b});
    a = b;
  }
}

// The polygon projected to 2D (xy) along the largest axis of its Newell normal, which is robust for
// non-planar and concave polygons; false when it has no area (all corners on a line or a point).
// *orientation: +1 or -1, the polygon's winding in the projection. kCorners: n known when
// compiled (4), or 0.
template <uint32_t kCorners>
[[gnu::always_inline]] inline bool project(const float* const* corners, uint32_t n, double* xy, double* orientation) {
  if (kCorners) n = kCorners;
  double normal[3] = {0, 0, 0};
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (uint32_t i = 0; i < n; ++i) {
    const float* a = corners[i];
    const float* b = corners[i + 1 == n ? 0 : i + 1];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      if (kCorners != 4) normal[k] += (double(a[k1]) - b[k1]) * (double(a[k2]) + b[k2]);
      lo[k] = std::min(lo[k], double(a[k]));  // as fmin and fmax: a NaN is passed over
      hi[k] = std::max(hi[k], double(a[k]));
    }
  }
  if (kCorners == 4) {  // the same normal, as the cross product of the diagonals: fewer operations
    const float *p0 = corners[0], *p1 = corners[1], *p2 = corners[2], *p3 = corners[3];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      normal[k] = (double(p2[k1]) - p0[k1]) * (double(p3[k2]) - p1[k2]) - (double(p2[k2]) - p0[k2]) * (double(p3[k1]) - p1[k1]);
    }
  }
  int drop = 2;
  if (std::fabs(normal[0]) >= std::fabs(normal[1]) && std::fabs(normal[0]) >= std::fabs(normal[2])) drop = 0;
  else if (std::fabs(normal[1]) >= std::fabs(normal[2])) drop = 1;
  double extent2 = 0;
  for (int k = 0; k < 3; ++k) extent2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
  // The dropped normal component is twice the projected area (its sign the winding there, the
  // other way round when y is dropped); relative to the size squared it says whether the polygon
  // has any area at all.
  if (!(std::fabs(normal[drop]) > 1e-12 * extent2)) return false;
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  for (uint32_t i = 0; i < n; ++i) {
    xy[2 * i] = corners[i][u];
    xy[2 * i + 1] = corners[i][v];
  }
  *orientation = (normal[drop] > 0) == (drop != 1) ? 1.0 : -1.0;
  return true;
}

// Positive for a left turn a -> b -> c in the polygon's own winding.
inline double turn(const double* xy, double orientation, uint32_t a, uint32_t b, uint32_t c) {
  return orientation * ((xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
                        (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]));
}

}  // namespace

Triangulation triangulate_polygon(const float* const* corners, uint32_t n, std::vector<uint32_t>* triangles,
                                  TriangulationScratch* s) {
  auto fan_from_first = [&] {
    for (uint32_t k = 1; k + 1 < n; ++k) triangles->insert(triangles->end(), {0, k, k + 1});
  };
  if (n > kMaxEarClipCorners) {
    fan_from_first();
    return Triangulation::kFanTooLarge;
  }
  s->xy.resize(2 * size_t{n});
  double* xy = s->xy.data();
  double orientation;
  if (!(n == 4 ? project<4>(corners, n, xy, &orientation) : project<0>(corners, n, xy, &orientation))) {
    fan_from_first();
    return Triangulation::kFanDegenerate;
  }
  auto turn = [&](uint32_t a, uint32_t b, uint32_t c) { return pfx_obj::turn(xy, orientation, a, b, c); };
  auto same_point = [&](uint32_t a, uint32_t b) { return xy[2 * a] == xy[2 * b] && xy[2 * a + 1] == xy[2 * b + 1]; };
  // A convex quadrilateral, as most quads are, without the walk: the triangles it would clip.
  if (n == 4 && turn(3, 0, 1) > 0 && turn(0, 1, 2) > 0 && turn(1, 2, 3) > 0 && turn(2, 3, 0) > 0) {
    triangles->insert(triangles->end(), {3, 0, 1, 3, 1, 2});
    return Triangulation::kEarClipped;
  }
  s->previous.resize(n);
  s->next.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    s->previous[i] = (i + n - 1) % n;
    s->next[i] = (i + 1) % n;
  }
  s->reflex.resize(n);
  for (uint32_t i = 0; i < n; ++i) s->reflex[i] = !(turn(s->previous[i], i, s->next[i]) > 0);

  // An ear: a convex corner whose triangle holds no reflex (or flat) corner of what remains.
  auto is_ear = [&](uint32_t i) {
    if (s->reflex[i]) return false;
    const uint32_t p = s->previous[i], q = s->next[i];
    for (uint32_t k = s->next[q]; k != p; k = s->next[k]) {
      if (!s->reflex[k] || same_point(k, p) || same_point(k, i) || same_point(k, q)) continue;
      if (turn(p, i, k) >= 0 && turn(i, q, k) >= 0 && turn(q, p, k) >= 0) return false;
    }
    return true;
  };

  uint32_t remaining = n, current = 0, misses = 0;
  while (remaining > 3) {
    if (!is_ear(current)) {
      current = s->next[current];
      if (++misses > remaining) {
        fan(current, s->next, remaining, triangles);
        return Triangulation::kFanSelfIntersecting;
      }
      continue;
    }
    const uint32_t p = s->previous[current], q = s->next[current];
    triangles->insert(triangles->end(), {p, current, q});
    s->next[p] = q;
    s->previous[q] = p;
    --remaining;
    s->reflex[p] = !(turn(s->previous[p], p, q) > 0);
    s->reflex[q] = !(turn(p, q, s->next[q]) > 0);
    current = q;
    misses = 0;
  }
  triangles->insert(triangles->end(), {s->previous[current], current, s->next[current]});
  return Triangulation::kEarClipped;
}

}  // namespace pfx_obj
