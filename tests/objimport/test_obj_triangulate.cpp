// Ear clipping, checked against geometry computed here: the triangles must cover exactly the
// polygon's area, each turning the polygon's way, each lying inside it.
#include <catch2/catch.hpp>

#include <cmath>

#include "obj_triangulate.hpp"

using pfx_obj::Triangulation;

namespace {

struct Polygon2 {
  std::vector<std::array<double, 2>> points;
};

double signed_area(const std::vector<std::array<double, 2>>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return a / 2;
}

bool inside(const std::vector<std::array<double, 2>>& p, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i][1] > y) != (p[j][1] > y) && x < (p[j][0] - p[i][0]) * (y - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
      in = !in;
  return in;
}

// Lays the 2D polygon into 3D by (x, y) -> x * axis_u + y * axis_v, so every plane and both
// windings can be tried; checks the triangulation in 2D.
void check_polygon(const std::vector<std::array<double, 2>>& p, const double axis_u[3], const double axis_v[3]) {
  std::vector<std::array<float, 3>> corners;
  for (const auto& q : p) {
    std::array<float, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(q[0] * axis_u[k] + q[1] * axis_v[k]);
    corners.push_back(c);
  }
  std::vector<const float*> pointers;
  for (auto& c : corners) pointers.push_back(c.data());
  std::vector<uint32_t> triangles;
  pfx_obj::TriangulationScratch scratch;
  Triangulation how = pfx_obj::triangulate_polygon(pointers.data(), static_cast<uint32_t>(p.size()), &triangles, &scratch);
  CHECK(how == Triangulation::kEarClipped);
  REQUIRE(triangles.size() == 3 * (p.size() - 2));
  const double area = signed_area(p);
  double total = 0;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    std::vector<std::array<double, 2>> tri = {p[triangles[t]], p[triangles[t + 1]], p[triangles[t + 2]]};
    const double a = signed_area(tri);
    // Same winding as the polygon. Collinear corners may leave a zero-area triangle, which covers
    // nothing; every other one lies inside the polygon.
    CHECK(a * area >= 0);
    total += a;
    const double cx = (tri[0][0] + tri[1][0] + tri[2][0]) / 3, cy = (tri[0][1] + tri[1][1] + tri[2][1]) / 3;
    if (a != 0) CHECK(inside(p, cx, cy));
  }
  CHECK(total == Approx(area).epsilon(1e-9));
}

const std::vector<std::vector<std::array<double, 2>>>& shapes() {
  static const std::vector<std::vector<std::array<double, 2>>> all = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},                                            // square
      {{0, 0}, {2, 0}, {1, 0.2}, {1, 2}},                                          // concave quad (dart)
      {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}},                            // L
      {{0, 0}, {4, 0}, {4, 4}, {3, 4}, {3, 1}, {1, 1}, {1, 4}, {0, 4}},            // U
      {{0, 0}, {2, 1}, {4, 0}, {3, 2}, {4, 4}, {2, 3}, {0, 4}, {1, 2}},            // star-ish, 4 reflex corners
      {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}},                            // collinear corners
      {{0, 0}, {5, 0}, {5, 5}, {4, 5}, {4, 1}, {3, 1}, {3, 5}, {2, 5}, {2, 1}, {1, 1}, {1, 5}, {0, 5}},  // comb
  };
  return all;
}

}  // namespace

TEST_CASE("obj triangulate: concave polygons in every plane and both windings", "[objimport][triangulate]") {
  const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
  const double tilt_u[3] = {0.6, 0.8, 0}, tilt_v[3] = {-0.48, 0.36, 0.8};
  const double* planes[][2] = {{x, y}, {y, x}, {x, z}, {z, x}, {y, z}, {z, y}, {tilt_u, tilt_v}, {tilt_v, tilt_u}};
  for (size_t s = 0; s < shapes().size(); ++s)
    for (auto& plane : planes) {
      INFO("shape " << s);
      check_polygon(shapes()[s], plane[0], plane[1]);
      auto reversed = shapes()[s];
      std::reverse(reversed.begin(), reversed.end());
      check_polygon(reversed, plane[0], plane[1]);
    }
}

TEST_CASE("obj triangulate: a circle of 2000 corners", "[objimport][triangulate]") {
  std::vector<std::array<double, 2>> circle;
  for (int i = 0; i < 2000; ++i) circle.push_back({std::cos(i * 2 * M_PI / 2000), std::sin(i * 2 * M_PI / 2000)});
  const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
  check_polygon(circle, x, y);
}

TEST_CASE("obj triangulate: degenerate polygons fall back to a fan", "[objimport][triangulate]") {
  const float line[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  const float same[4][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  for (auto* points : {line, same}) {
    const float* pointers[4] = {points[0], points[1], points[2], points[3]};
    std::vector<uint32_t> triangles;
    pfx_obj::TriangulationScratch scratch;
    CHECK(pfx_obj::triangulate_polygon(pointers, 4, &triangles, &scratch) == Triangulation::kFanDegenerate);
    CHECK(triangles == std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
  }
}

// Ear clipping walks from corner 0: in a convex quadrilateral corner 0 is an ear, giving (3 0 1),
// and the rest is (3 1 2). A concave one (a dart, corner 2 reflex) has no ear at 0 (its triangle
// 3 0 1 holds corner 2), so the walk moves on to corner 1 — (0 1 2) — and ends with (0 2 3).
// Worked out by hand, so a quick path for quadrilaterals must cut them as the walk does.
TEST_CASE("obj triangulate: quadrilaterals are cut where ear clipping cuts them", "[objimport][triangulate]") {
  const float square[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const float dart[4][3] = {{0, 0, 0}, {2, 1, 0}, {0.5f, 0.5f, 0}, {1, 2, 0}};
  const float tilted[4][3] = {{0, 0, 0}, {1, 0, 0.2f}, {1, 1, 0.1f}, {0, 1, 0.3f}};  // not planar
  for (auto [points, expected] : {std::pair{square, std::vector<uint32_t>{3, 0, 1, 3, 1, 2}},
                                  std::pair{dart, std::vector<uint32_t>{0, 1, 2, 0, 2, 3}},
                                  std::pair{tilted, std::vector<uint32_t>{3, 0, 1, 3, 1, 2}}}) {
    for (bool reversed : {false, true}) {  // the other winding keeps corner 2 reflex in the dart
      const float* pointers[4];
      for (int k = 0; k < 4; ++k) pointers[k] = points[reversed ? (4 - k) % 4 : k];
      std::vector<uint32_t> triangles;
      pfx_obj::TriangulationScratch scratch;
      CHECK(pfx_obj::triangulate_polygon(pointers, 4, &triangles, &scratch) == Triangulation::kEarClipped);
      CHECK(triangles == expected);
    }
  }
}
