// View-space geometry for culling, GL-free and in double precision: the perspective of a frame's
// projection, the planes of the sub-frustum behind a rectangle of pixels, and sphere tests.
//
// A pixel at window position (x, y) of a W x H frame sees the view-space ray
//   (x_view, y_view) / depth = ((2x/W - 1 + offset_x) / scale_x, (2y/H - 1 + offset_y) / scale_y),
// the inverse of the perspective part of an OpenGL projection matrix P (scale = P[0], P[5];
// offset = P[8], P[9]; w = -z). The shading pass reconstructs positions with the same formula.
#pragma once

#include <string>

#include <pfx/effect.h>

namespace pfx_tiledlights {

struct Perspective {
  double scale_x = 1, scale_y = 1, offset_x = 0, offset_y = 0;
};

// False with *error when the projection is not a perspective one (w must be -z_view).
bool perspective_of(const pfx_camera& camera, Perspective* out, std::string* error);

// The four side planes through the eye of the sub-frustum behind pixels [x0, x1) x [y0, y1) (pixel
// edges in window coordinates), as inward unit normals: a point p is inside when dot(n, p) >= 0
// for all four.
struct SidePlanes {
  double n[4][3];
};
SidePlanes side_planes(const Perspective& perspective, int width, int height, double x0, double x1, double y0,
                       double y1);

// Whether a sphere (view-space centre, radius) reaches the inside of every plane (conservative:
// it may say yes for a sphere near an edge of the frustum that misses it, never no for one that
// touches it).
bool sphere_touches(const SidePlanes& planes, const double centre[3], double radius);
// Whether the sphere reaches view depths (distance along -Z) between near and far.
inline bool sphere_touches_depths(const double centre[3], double radius, double near_depth, double far_depth) {
  const double depth = -centre[2];
  return depth + radius >= near_depth && depth - radius <= far_depth;
}

// Inverse of a column-major 4x4 matrix (Gauss-Jordan, partial pivoting); false when singular.
bool invert_matrix(const double m[16], double out[16]);

// The pixels [first, last) of tile j when count tiles share a span of size pixels, by the same
// integer rule the shader uses to find a pixel's tile: tile = pixel * count / size.
inline int grid_tile_first_pixel(int j, int count, int size) {
  return static_cast<int>((static_cast<long long>(j) * size + count - 1) / count);
}

}  // namespace pfx_tiledlights
