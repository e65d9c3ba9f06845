// The level plans: the pyramid's halving (from a half or a quarter), never below one pixel, clamped to
// the frame; the level weights and the automatic share rule.
#include <catch2/catch.hpp>

#include "bloom_levels.hpp"
#include "bloom_params.hpp"

using pfx_bloom::plan_levels;

TEST_CASE("automatic levels at 1920x1080 are the pyramid's six", "[bloom][levels]") {
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

namespace {

pfx_bloom::Settings with(int mode, int levels = 0) {
  pfx_value values[pfx_bloom::PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::PARAM_COUNT; ++i) values[i] = pfx_bloom::kParams[i].default_value;
  values[pfx_bloom::PARAM_MODE].v[0] = mode;
  values[pfx_bloom::PARAM_LEVELS].v[0] = levels;
  return pfx_bloom::settings_from(values);
}

}  // namespace

TEST_CASE("mgf buffers start at a quarter of the frame, gaussian has one buffer at its downscale", "[bloom][levels]") {
  // Both round up, so that every pixel is read: ceil(size / d) blocks with the frame centred on them.
  const auto mgf = pfx_bloom::plan_for(with(pfx_bloom::MODE_MGF), 1920, 1080);
  REQUIRE(mgf.count == 5);  // Kawase's 480x270 ... 30x16; 15x8 is below the automatic minimum of 16
  CHECK((mgf.width[0] == 480 && mgf.height[0] == 270));
  CHECK((mgf.width[4] == 30 && mgf.height[4] == 17));  // 135 is odd: 68, 34, 17 cover it
  CHECK(pfx_bloom::max_levels(1917, 1079, 4) == 9);
  // The halving's count, counted on the rounded-down sizes (479x269 ... 1x1), with buffers that cover
  // the frame: 1917 = 480 * 4 - 3 (1 pixel of padding before, 2 after), 1079 = 270 * 4 - 1.
  const auto odd = pfx_bloom::plan_for(with(pfx_bloom::MODE_MGF, 16), 1917, 1079);
  REQUIRE(odd.count == 9);
  CHECK((odd.width[0] == 480 && odd.height[0] == 270 && odd.block == 4 && odd.pad_x == 1 && odd.pad_y == 0));
  CHECK((odd.width[2] == 120 && odd.height[2] == 68));  // 135 texels -> 68, the last half black
  CHECK((odd.width[8] == 2 && odd.height[8] == 2));
  CHECK(pfx_bloom::plan_for(with(pfx_bloom::MODE_MGF, 16), 3, 3).count == 1);
  pfx_bloom::Settings g = with(pfx_bloom::MODE_GAUSSIAN, 5);
  g.downscale = 3;
  const auto one = pfx_bloom::plan_for(g, 1920, 1081);
  REQUIRE(one.count == 1);
  CHECK((one.width[0] == 640 && one.height[0] == 361));  // 1081 = 361 * 3 - 2: one row of padding on each side
  CHECK((one.block == 3 && one.pad_x == 0 && one.pad_y == 1));
  CHECK(pfx_bloom::blocks_covering(2, 4) == 1);
  CHECK(pfx_bloom::padding_before(2, 4) == 1);  // 1 before, 1 after
  CHECK(pfx_bloom::padding_before(19, 4) == 0);  // 20 - 19: the one row after
  CHECK(pfx_bloom::plan_for(with(pfx_bloom::MODE_CHAIN13), 1920, 1080).count == 6);
}

TEST_CASE("level weights: equal for the chains, ratio^i for mgf, and the automatic share rule", "[bloom][levels]") {
  double w[pfx_bloom::kMaxLevels];
  pfx_bloom::level_weights(with(pfx_bloom::MODE_CHAIN), 4, w);
  for (int i = 0; i < 4; ++i) CHECK(w[i] == Approx(0.25));
  pfx_bloom::level_weights(with(pfx_bloom::MODE_MGF), 3, w);  // ratio 2: 1, 2, 4 over 7
  CHECK(w[0] == Approx(1.0 / 7));
  CHECK(w[2] == Approx(4.0 / 7));
  pfx_bloom::Settings s = with(pfx_bloom::MODE_CHAIN);
  s.auto_min_share = 0.2;  // levels carry 1/n: at most 5 levels
  CHECK(pfx_bloom::plan_for(s, 1920, 1080).count == 5);
  s = with(pfx_bloom::MODE_MGF);
  s.mgf_ratio = 0.5;
  s.auto_min_share = 0.1;  // 1, 1/2, 1/4, 1/8 over 1.875: the fourth carries 0.067
  CHECK(pfx_bloom::plan_for(s, 1920, 1080).count == 3);
  s.levels = 5;  // an explicit count is kept
  CHECK(pfx_bloom::plan_for(s, 1920, 1080).count == 5);
}
