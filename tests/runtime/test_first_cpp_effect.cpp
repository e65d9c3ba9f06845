// The smallest C++ plugin of docs/sdk.md (tests/fixtures/first_effect), written with the C++ kit,
// over real GL: its parameter as described, its picture against values computed here, and no pass
// while it would change nothing.
#include <catch2/catch.hpp>

#include "gl_test_support.hpp"

using pfx::app::Image;

TEST_CASE("the C++ example plugin describes its parameter by name as written", "[first_effect]") {
  pfx::test::ChainRig rig(PFX_TEST_FIRST_EFFECT_PLUGIN);
  rig.add("tint");
  const auto* info = rig.registry->find_effect("tint");
  REQUIRE(info != nullptr);
  const pfx_effect_desc* effect = info->desc;
  REQUIRE(effect->param_count == 1);
  const pfx_param_desc& tint = effect->params[0];
  CHECK(std::string(tint.id) == "tint");
  CHECK(std::string(tint.label) == "Tint");
  CHECK(std::string(tint.unit).empty());   // left out: no unit
  CHECK(std::string(tint.group).empty());  // left out: no group
  CHECK(tint.type == PFX_PARAM_COLOR);
  CHECK(tint.hard_min == 0);
  CHECK(tint.hard_max == 16);
  CHECK(tint.display_min == 0);
  CHECK(tint.display_max == 1);
  CHECK(tint.step == Approx(0.01));  // left out: a hundredth of the display range
  CHECK(tint.flags == 0);
  CHECK(tint.default_value.v[0] == 1);
  CHECK(tint.default_value.v[1] == 1);
  CHECK(tint.default_value.v[2] == 1);
}

TEST_CASE("the C++ example plugin tints every pixel, keeps alpha, and skips itself when white", "[first_effect]") {
  const Image input = pfx::test::test_image(23, 11);
  pfx::test::ChainRig rig(PFX_TEST_FIRST_EFFECT_PLUGIN);
  rig.add("tint");
  rig.set("tint.tint=0.5,2,0.25");
  Image output = rig.render(input);
  REQUIRE(rig.chain->report().passes.size() == 1);
  const float tint[3] = {0.5f, 2.0f, 0.25f};
  for (size_t i = 0; i < input.rgba.size(); ++i) {
    // Two half conversions (upload, render target): 2 half ulps at most. A tint off by 0.4% fails.
    const float expected = i % 4 == 3 ? input.rgba[i] : input.rgba[i] * tint[i % 4];
    REQUIRE(output.rgba[i] == Approx(expected).epsilon(1.0 / 512).margin(1e-6));
  }

  rig.set("tint.tint=1,1,1");
  output = rig.render(input);
  CHECK(rig.chain->report().passes.empty());
  CHECK(rig.chain->report().effects_skipped == std::vector<std::string>{"tint"});
  for (size_t i = 0; i < input.rgba.size(); ++i) REQUIRE(output.rgba[i] == Approx(input.rgba[i]).epsilon(1.0 / 1024));
}
