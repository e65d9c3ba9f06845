// The gather's ring samples and work plan, on their own.
#include <catch2/catch.hpp>

#include <cmath>

#include "dof_gather_plan.hpp"
#include "dof_rings.hpp"

using namespace pfx_dof;

TEST_CASE("ring samples: exactly N, inside the unit disc, areas summing to pi, spread evenly", "[dof][rings]") {
  for (int n : {8, 16, 17, 32, 64, 100, 128, 256}) {
    const auto samples = ring_samples(n);
    REQUIRE(samples.size() == static_cast<size_t>(n));
    double area = 0, cx = 0, cy = 0, second_moment = 0;
    for (const RingSample& s : samples) {
      CHECK(std::hypot(s.x, s.y) < 1.0);
      area += s.area;
      cx += s.area * s.x;
      cy += s.area * s.y;
      second_moment += s.area * (s.x * s.x + s.y * s.y);
    }
    INFO(n << " samples");
    CHECK(area == Approx(M_PI).epsilon(1e-6));
    // Balanced around the centre, and the disc's second moment (pi / 2) within 5%.
    CHECK(std::fabs(cx) < 1e-5);
    CHECK(std::fabs(cy) < 1e-5);
    CHECK(second_moment == Approx(M_PI / 2).epsilon(0.05));
  }
  // 16 and 64 fill their rings exactly in proportion to area.
  int inner = 0;
  for (const RingSample& s : ring_samples(64)) inner += std::hypot(s.x, s.y) < 0.25;
  CHECK(inner == 4);
}

TEST_CASE("gather plan: half resolution rounds odd sides up, tiles cover the frame, dilation follows the CoC cap",
          "[dof][rings]") {
  Settings s;
  s.resolution = RESOLUTION_HALF;
  s.max_coc = 32;
  GatherPlan p = plan_gather(1917, 1079, s);
  CHECK(p.work_width == 959);
  CHECK(p.work_height == 540);
  CHECK(p.tile == 8);
  CHECK(p.tiles_width == 120);  // 1917 / 16 rounded up
  CHECK(p.tiles_height == 68);
  CHECK(p.dilation == 1);
  s.resolution = RESOLUTION_FULL;
  s.max_coc = 128;
  p = plan_gather(1, 1, s);
  CHECK((p.work_width == 1 && p.work_height == 1 && p.tiles_width == 1 && p.tiles_height == 1));
  CHECK(p.dilation == 4);
}
