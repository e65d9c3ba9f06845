// pfx_view_depth (pfx/depth.h) against depths computed independently: build the projection
// matrix, project a view-space point at a known depth, take its window z as a GPU would store
// it, and check that decoding gives the depth back.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <pfx/depth.h>

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Column-major like GL: m[column * 4 + row].
using Mat4 = std::array<double, 16>;

// gluPerspective / glm::perspective (right-handed, clip z in [-w, w]); far may be infinite.
Mat4 gl_perspective(double fovy, double aspect, double n, double f) {
  const double cot = 1.0 / std::tan(fovy / 2.0);
  Mat4 m{};
  m[0] = cot / aspect;
  m[5] = cot;
  m[11] = -1.0;
  if (std::isinf(f)) {
    m[10] = -1.0;
    m[14] = -2.0 * n;
  } else {
    m[10] = -(f + n) / (f - n);
    m[14] = -2.0 * f * n / (f - n);
  }
  return m;
}

// Reversed Z for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): clip z / w is 1 at near, 0 at far.
Mat4 reversed_perspective(double fovy, double aspect, double n, double f) {
  const double cot = 1.0 / std::tan(fovy / 2.0);
  Mat4 m{};
  m[0] = cot / aspect;
  m[5] = cot;
  m[11] = -1.0;
  if (std::isinf(f)) {
    m[10] = 0.0;
    m[14] = n;
  } else {
    m[10] = n / (f - n);
    m[14] = f * n / (f - n);
  }
  return m;
}

// The depth a GPU stores for a point `depth` metres in front of the camera (view z = -depth),
// slightly off-axis so x and y take part. With the default glDepthRange(0, 1), window z is
// (ndc z + 1) / 2 for -1..1 clip and ndc z itself for zero-to-one clip.
double stored_depth(const Mat4& m, double depth, bool zero_to_one) {
  const double p[4] = {0.3 * depth, -0.2 * depth, -depth, 1.0};
  double clip[4] = {0, 0, 0, 0};
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) clip[row] += m[column * 4 + row] * p[column];
  const double ndc_z = clip[2] / clip[3];
  return zero_to_one ? ndc_z : 0.5 * ndc_z + 0.5;
}

struct Case {
  double near_plane, far_plane;
};

std::vector<double> depths_between(double n, double f, bool include_far) {
  std::vector<double> depths = {n, n * 1.5, 1.0, 2.5, 10.0, 37.25};
  if (std::isinf(f)) {
    depths.insert(depths.end(), {1000.0, 123456.0});
  } else {
    depths.insert(depths.end(), {0.5 * (n + f), 0.9 * f});
    if (include_far) depths.push_back(f);
  }
  std::vector<double> inside;
  for (double d : depths)
    if (d >= n && d <= f) inside.push_back(d);
  return inside;
}

void check_recovers(pfx_depth_encoding encoding, const Mat4& m, bool zero_to_one, Case c,
                    bool include_far = true) {
  for (double depth : depths_between(c.near_plane, c.far_plane, include_far)) {
    const double stored = stored_depth(m, depth, zero_to_one);
    const double decoded = pfx_view_depth(stored, encoding, c.near_plane, c.far_plane);
    INFO("near " << c.near_plane << " far " << c.far_plane << " depth " << depth << " stored "
                 << stored << " decoded " << decoded);
    CHECK(std::abs(decoded - depth) <= 1e-6 * depth);
  }
}

}  // namespace

TEST_CASE("the hand-written GL projection matches glm", "[depth]") {
  const glm::dmat4 finite = glm::perspective(0.8, 1.5, 0.1, 100.0);
  const glm::dmat4 infinite = glm::infinitePerspective(0.8, 1.5, 0.1);
  const Mat4 ours_finite = gl_perspective(0.8, 1.5, 0.1, 100.0);
  const Mat4 ours_infinite = gl_perspective(0.8, 1.5, 0.1, kInf);
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) {
      CHECK(ours_finite[column * 4 + row] == Approx(finite[column][row]).margin(1e-12));
      CHECK(ours_infinite[column * 4 + row] == Approx(infinite[column][row]).margin(1e-12));
    }
}

TEST_CASE("hardware depth with a finite far plane decodes to view depth", "[depth]") {
  for (Case c : {Case{0.1, 100.0}, Case{0.1, 1000.0}, Case{1.0, 50.0}, Case{0.05, 20000.0}})
    check_recovers(PFX_DEPTH_HARDWARE, gl_perspective(0.9, 16.0 / 9.0, c.near_plane, c.far_plane),
                   false, c);
}

TEST_CASE("hardware depth with an infinite far plane decodes to view depth", "[depth]") {
  for (Case c : {Case{0.1, kInf}, Case{1.0, kInf}})
    check_recovers(PFX_DEPTH_HARDWARE, gl_perspective(0.9, 16.0 / 9.0, c.near_plane, kInf), false,
                   c);
  CHECK(pfx_view_depth(1.0, PFX_DEPTH_HARDWARE, 0.1, kInf) == kInf);
  CHECK(pfx_view_depth(0.0, PFX_DEPTH_HARDWARE, 0.1, kInf) == Approx(0.1).epsilon(1e-12));
}

TEST_CASE("reversed zero-to-one depth with a finite far plane decodes to view depth", "[depth]") {
  // The far plane itself is checked in the test case below.
  for (Case c : {Case{0.1, 100.0}, Case{0.1, 1000.0}, Case{1.0, 50.0}, Case{0.05, 20000.0}})
    check_recovers(PFX_DEPTH_HARDWARE_REVERSED,
                   reversed_perspective(0.9, 16.0 / 9.0, c.near_plane, c.far_plane), true, c,
                   false);
  CHECK(pfx_view_depth(1.0, PFX_DEPTH_HARDWARE_REVERSED, 0.1, 100.0) == Approx(0.1).epsilon(1e-12));
}

// A stored 0 is exactly the far plane: it decodes to far, as a stored 1 does for standard depth.
TEST_CASE("reversed zero-to-one depth at a finite far plane decodes to far", "[depth]") {
  for (Case c : {Case{0.1, 100.0}, Case{1.0, 50.0}}) {
    const Mat4 m = reversed_perspective(0.9, 16.0 / 9.0, c.near_plane, c.far_plane);
    INFO("near " << c.near_plane << " far " << c.far_plane);
    CHECK(pfx_view_depth(stored_depth(m, c.far_plane, true), PFX_DEPTH_HARDWARE_REVERSED,
                         c.near_plane, c.far_plane) == Approx(c.far_plane).epsilon(1e-12));
  }
}

TEST_CASE("reversed zero-to-one depth with an infinite far plane decodes to view depth",
          "[depth]") {
  for (Case c : {Case{0.1, kInf}, Case{1.0, kInf}})
    check_recovers(PFX_DEPTH_HARDWARE_REVERSED,
                   reversed_perspective(0.9, 16.0 / 9.0, c.near_plane, kInf), true, c);
  CHECK(pfx_view_depth(0.0, PFX_DEPTH_HARDWARE_REVERSED, 0.1, kInf) == kInf);
}

TEST_CASE("depth past the far plane decodes as +infinity", "[depth]") {
  CHECK(pfx_view_depth(1.5, PFX_DEPTH_HARDWARE, 0.1, 100.0) == kInf);
  CHECK(pfx_view_depth(1.5, PFX_DEPTH_HARDWARE, 0.1, kInf) == kInf);
  CHECK(pfx_view_depth(-0.25, PFX_DEPTH_HARDWARE_REVERSED, 0.1, 100.0) == kInf);
  CHECK(pfx_view_depth(-0.25, PFX_DEPTH_HARDWARE_REVERSED, 0.1, kInf) == kInf);
}

TEST_CASE("linear depth passes through and NaN stays NaN", "[depth]") {
  for (double d : {0.0, 0.1, 3.25, 1e6})
    CHECK(pfx_view_depth(d, PFX_DEPTH_LINEAR, 0.1, 100.0) == d);
  CHECK(pfx_view_depth(kInf, PFX_DEPTH_LINEAR, 0.1, 100.0) == kInf);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (pfx_depth_encoding e : {PFX_DEPTH_HARDWARE, PFX_DEPTH_HARDWARE_REVERSED, PFX_DEPTH_LINEAR})
    for (double f : {100.0, kInf}) CHECK(std::isnan(pfx_view_depth(nan, e, 0.1, f)));
  CHECK(std::isnan(pfx_view_depth(0.5, PFX_DEPTH_NONE, 0.1, 100.0)));
}
