// The dense case's bound on exact methods (light_reach.hpp), on a frame small enough to count by
// hand: 2x2 pixels, the top row empty, two surface points at view (-1, -1, -2) and (1, -1, -2),
// five lights. Worked out per light, view space, pixel 0 facing the camera (n = +z), pixel 1 facing
// +x:
//   L1 (-1,-1,-1) r 2:     pixel 0 d 1, N.L 1 > 0: lit; pixel 1 d 2.24: out of range.
//   L2 ( 0,-1,-3) r 3:     both in range (d 1.41), both behind the surface (N.L -1): reaching only.
//   L3 ( 2,-1,-2) r 1.5:   pixel 0 d 3: out; pixel 1 d 1, N.L 1: lit.
//   L4 ( 1,-1,-2) derived: intensity 1, white, cutoff 0.05: r = sqrt(19) = 4.36. Pixel 0 d 2 with
//                          N.L exactly 0: reaching only; pixel 1: the light is at the point: lit.
//   L5 (-1,-1,-2) r 5, black: reaches both, lights neither.
// Pixel 0: 4 reaching, 1 lit; pixel 1: 4 reaching, 2 lit. Means over the 2 pixels with geometry:
// 4 and 1.5. With 2-pixel tiles (the whole frame one tile) every pixel sums the 5 lights reaching
// one of its tile's points; with 1-pixel tiles, its own 4.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "light_reach.hpp"

namespace {

struct Case {
  std::vector<pfx_light> lights;
  std::vector<float> depth, normal;
  pfx_frame frame{};
};

// view: column-major; to_world maps a view-space point or direction (w = 1 or 0) to world space.
template <class ToWorld>
Case make_case(const float (&view)[16], ToWorld to_world) {
  Case c;
  const float positions[5][3] = {{-1, -1, -1}, {0, -1, -3}, {2, -1, -2}, {1, -1, -2}, {-1, -1, -2}};
  const float ranges[5] = {2, 3, 1.5f, 0, 5};
  for (int i = 0; i < 5; ++i) {
    pfx_light l{};
    to_world(positions[i], 1.0f, l.position);
    l.range = ranges[i];
    for (float& channel : l.color) channel = i == 4 ? 0.0f : 1.0f;
    l.intensity = 1;
    c.lights.push_back(l);
  }
  const float inf = INFINITY;
  c.depth = {2, 2, inf, 0};  // rows bottom first: the top row has no geometry
  const float facing[2][3] = {{0, 0, 1}, {1, 0, 0}};
  c.normal.assign(16, 0.0f);
  for (int p = 0; p < 2; ++p) to_world(facing[p], 0.0f, &c.normal[p * 4]);
  c.frame.struct_size = sizeof c.frame;
  c.frame.width = c.frame.height = 2;
  c.frame.depth_encoding = PFX_DEPTH_LINEAR;
  c.frame.lights = c.lights.data();
  c.frame.light_count = 5;
  c.frame.light_struct_size = sizeof(pfx_light);
  for (int i = 0; i < 16; ++i) c.frame.camera.view[i] = view[i];
  const float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -0.2f, 0};
  for (int i = 0; i < 16; ++i) c.frame.camera.projection[i] = projection[i];
  c.frame.camera.near_plane = 0.1f;
  c.frame.camera.far_plane = 100;
  return c;
}

}  // namespace

TEST_CASE("light reach: lights reaching each pixel and lights whose term is not zero, counted by hand",
          "[bench][lights]") {
  SECTION("the camera at the origin looking down -z") {
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    Case c = make_case(identity, [](const float* v, float, float* out) {
      for (int k = 0; k < 3; ++k) out[k] = v[k];
    });
    const pfx::bench::LightReach r = pfx::bench::count_light_reach(c.frame, c.depth, c.normal, 0.05, 2);
    CHECK(r.pixels == 2);
    CHECK(r.reaching_mean == Approx(4.0));
    CHECK(r.lit_mean == Approx(1.5));
    CHECK(r.tile_reaching_mean == Approx(5.0));
    CHECK(pfx::bench::count_light_reach(c.frame, c.depth, c.normal, 0.05, 1).tile_reaching_mean == Approx(4.0));
  }
  SECTION("the same view-space scene seen by a turned, moved camera: the normals turn with it") {
    // view: x_v = z_w, y_v = y_w, z_v = -x_w - 5; so world = (-(z_v + 5), y_v, x_v) for points and
    // (-z_v, y_v, x_v) for directions.
    const float turned[16] = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, -5, 1};
    Case c = make_case(turned, [](const float* v, float w, float* out) {
      out[0] = -(v[2] + 5 * w);
      out[1] = v[1];
      out[2] = v[0];
    });
    const pfx::bench::LightReach r = pfx::bench::count_light_reach(c.frame, c.depth, c.normal, 0.05, 2);
    CHECK(r.pixels == 2);
    CHECK(r.reaching_mean == Approx(4.0));
    CHECK(r.lit_mean == Approx(1.5));
  }
}
