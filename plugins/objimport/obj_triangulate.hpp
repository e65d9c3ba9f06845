// Polygons to triangles by ear clipping: concave polygons come out right, in the polygon's own
// winding. The polygon is projected onto the plane of its Newell normal; a polygon whose normal
// vanishes (all corners on a line or a point), that clips to no ear (self-intersecting), or has
// more than kMaxEarClipCorners corners is cut as a fan from its first corner instead, and the
// caller is told so it can warn. Corners on a straight edge may end up in a zero-area triangle
// (it covers nothing, and keeps the count at n - 2).
#pragma once

#include <cstdint>
#include <vector>

namespace pfx_obj {

constexpr uint32_t kMaxEarClipCorners = 4096;

enum class Triangulation { kEarClipped, kFanDegenerate, kFanSelfIntersecting, kFanTooLarge };

// corners: n >= 3 positions (x, y, z each). Appends n - 2 triangles to `triangles` as corner
// numbers 0..n-1 (three per triangle). `scratch` is reused between calls to save allocations.
struct TriangulationScratch {
  std::vector<double> xy;
  std::vector<uint32_t> previous, next;
  std::vector<uint8_t> reflex;
};
Triangulation triangulate_polygon(const float* const* corners, uint32_t n, std::vector<uint32_t>* triangles,
                                  TriangulationScratch* scratch);

}  // namespace pfx_obj
