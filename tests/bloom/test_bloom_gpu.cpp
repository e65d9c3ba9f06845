// The GPU chain against its CPU model (PFX_REFERENCE_MODEL) over sizes and settings, and the
// parameters' effects that need no model: no-op, alpha, levels.
#include <catch2/catch.hpp>

#include <cmath>

#include "bloom_rig.hpp"

using namespace bloom_test;

TEST_CASE("the GPU chain matches the CPU model at the defaults", "[bloom][model]") {
  Rig rig;
  for (auto [w, h] : {std::pair{64, 48}, std::pair{37, 23}, std::pair{100, 7}}) {
    Rendered r = rig.render(scene(w, h));
    REQUIRE(r.levels >= 1);
    require_matches_model(r);
  }
}

TEST_CASE("the GPU chain matches the CPU model for every level count", "[bloom][model]") {
  Rig rig;
  const Picture input = scene(80, 60);
  for (int levels = 1; levels <= 6; ++levels) {
    rig.set("bloom.levels=" + std::to_string(levels));
    Rendered r = rig.render(input);
    REQUIRE(r.levels == std::min(levels, 6));
    REQUIRE(r.passes == size_t(2 * r.levels));
    require_matches_model(r);
  }
}

TEST_CASE("the GPU chain matches the CPU model with knee, luminance, tint, clamp and strength", "[bloom][model]") {
  Rig rig;
  const Picture input = scene(48, 40);
  const char* const settings[][3] = {
      {"bloom.knee=0.5", "bloom.threshold=1", "bloom.strength=2"},
      {"bloom.measure=luminance", "bloom.threshold=0.5", "bloom.knee=0.25"},
      {"bloom.tint=1,0.5,0.25", "bloom.strength=3", "bloom.levels=3"},
      {"bloom.firefly_clamp=4", "bloom.threshold=0", "bloom.levels=2"},
      {"bloom.threshold=0", "bloom.knee=3", "bloom.strength=0.5"}};  // knee limited to the threshold
  for (const auto& group : settings) {
    Rig fresh;
    for (const char* s : group) fresh.set(s);
    INFO(group[0] << " " << group[1] << " " << group[2]);
    Rendered r = fresh.render(input);
    require_matches_model(r);
  }
}

TEST_CASE("the tolerance is tight enough to catch a 10% wrong strength", "[bloom][model]") {
  Rig rig;
  rig.set("bloom.levels=3");
  Rendered r = rig.render(scene(64, 48));
  require_matches_model(r);
  Rig stronger;
  stronger.set("bloom.levels=3");
  stronger.set("bloom.strength=1.1");
  Rendered wrong = stronger.render(scene(64, 48));
  CHECK(worst_error_ratio(r.output, wrong.model, r.input, r.levels) > 1.0);
  Rig shallower;
  shallower.set("bloom.levels=2");
  Rendered fewer = shallower.render(scene(64, 48));
  CHECK(worst_error_ratio(r.output, fewer.model, r.input, r.levels) > 1.0);
}

TEST_CASE("strength 0, a black tint or a zero clamp run no pass and leave the frame as it was", "[bloom][noop]") {
  for (const char* setting : {"bloom.strength=0", "bloom.tint=0", "bloom.firefly_clamp=0"}) {
    Rig rig;
    rig.set(setting);
    Picture input = scene(16, 12);
    input.at(3, 4)[1] = std::nanf("");  // even a NaN is passed through untouched: nothing ran
    Rendered r = rig.render(input);
    INFO(setting);
    CHECK(r.passes == 0);
    CHECK(rig.chain().report().effects_skipped == std::vector<std::string>{"bloom"});
    CHECK(rig.chain().report().peak_target_bytes == 0);
    for (size_t i = 0; i < input.rgba.size(); ++i)
      REQUIRE((r.output.rgba[i] == r.input.rgba[i] || (std::isnan(r.output.rgba[i]) && std::isnan(r.input.rgba[i]))));
  }
}

TEST_CASE("alpha passes through and the bloom only adds light", "[bloom]") {
  Rig rig;
  Picture input = scene(32, 24);
  for (int y = 0; y < input.height; ++y)
    for (int x = 0; x < input.width; ++x) input.at(x, y)[3] = float((x + y) % 5) / 4.0f;
  Rendered r = rig.render(input);
  for (size_t i = 0; i < r.input.rgba.size(); ++i) {
    if (i % 4 == 3)
      REQUIRE(r.output.rgba[i] == r.input.rgba[i]);
    else
      REQUIRE(r.output.rgba[i] >= r.input.rgba[i]);
  }
}
