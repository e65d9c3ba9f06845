// The pyramid's level plan: the seed's halving, never below one pixel, clamped to the frame.
#include <catch2/catch.hpp>

#include "bloom_levels.hpp"

using pfx_bloom::plan_levels;

TEST_CASE("automatic levels at 1920x1080 are the seed's six", "[bloom][levels]") {
  const auto plan = plan_levels(1920, 1080, 0, 16);
  REQUIRE(plan.count == 6);
  const int widths[6] = {960, 480, 240, 120, 60, 30}, heights[6] = {540, 270, 135, 67, 33, 16};
  for (int i = 0; i < 6; ++i) {
    CHECK(plan.width[i] == widths[i]);
    CHECK(plan.height[i] == heights[i]);
  }
  CHECK(plan_levels(1280, 720, 0, 16).count == 5);  // 640x360 ... 40x22; 20x11 would be too small
  CHECK(plan_levels(1280, 720, 0, 8).count == 6);
  CHECK(plan_levels(64, 48, 0, 16).count == 1);     // level 0 is always there
}

TEST_CASE("requested levels are clamped to what the frame allows", "[bloom][levels]") {
  CHECK(pfx_bloom::max_levels(1, 1) == 1);
  CHECK(pfx_bloom::max_levels(2, 3) == 1);
  CHECK(pfx_bloom::max_levels(1917, 1079) == 10);
  CHECK(pfx_bloom::max_levels(4096, 16) == 12);
  CHECK(pfx_bloom::max_levels(16384, 16384) == 14);

  auto tiny = plan_levels(1, 1, 6, 16);
  REQUIRE(tiny.count == 1);
  CHECK((tiny.width[0] == 1 && tiny.height[0] == 1));
  auto odd = plan_levels(2, 3, 3, 16);
  REQUIRE(odd.count == 1);
  CHECK((odd.width[0] == 1 && odd.height[0] == 1));
  auto wide = plan_levels(4096, 16, 16, 16);
  REQUIRE(wide.count == 12);
  CHECK((wide.width[3] == 256 && wide.height[3] == 1));
  CHECK((wide.width[11] == 1 && wide.height[11] == 1));
  auto seed = plan_levels(1917, 1079, 6, 16);
  REQUIRE(seed.count == 6);
  CHECK((seed.width[0] == 958 && seed.height[0] == 539));
  CHECK((seed.width[5] == 29 && seed.height[5] == 16));
}
