// The GPU against its CPU model (PFX_REFERENCE_MODEL), every mode, over sizes and settings, and the
// parameters' effects that need no model: no-op, alpha, levels.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bloom_levels.hpp"
#include "bloom_rig.hpp"
#include "demo_image.hpp"

using namespace bloom_test;

TEST_CASE("every mode on the GPU matches its CPU model at the defaults", "[bloom][model]") {
  for (const char* mode : kModes) {
    Rig rig;
    rig.set(std::string("bloom.mode=") + mode);
    for (auto [w, h] : {std::pair{64, 48}, std::pair{37, 23}, std::pair{100, 7}}) {
      Rendered r = rig.render(scene(w, h));
      REQUIRE(r.levels >= 1);
      require_matches_model(r);
    }
  }
}

TEST_CASE("the GPU pyramids match the CPU model for every level count", "[bloom][model]") {
  const Picture input = scene(80, 60);
  for (const char* mode : {"chain", "chain13", "mgf"}) {
    Rig rig;
    rig.set(std::string("bloom.mode=") + mode);
    const int most = pfx_bloom::max_levels(80, 60, std::string(mode) == "mgf" ? 4 : 2);
    for (int levels = 1; levels <= 6; ++levels) {
      rig.set("bloom.levels=" + std::to_string(levels));
      Rendered r = rig.render(input);
      INFO(mode << " levels=" << levels);
      REQUIRE(r.levels == std::min(levels, most));
      // chains: bright, down and up per level, composite; mgf: bright, two blurs per buffer, composite
      REQUIRE(r.passes == size_t(std::string(mode) == "mgf" ? 2 * r.levels + 2 : 2 * r.levels));
      require_matches_model(r);
    }
  }
}

TEST_CASE("every mode matches the CPU model with knee, luminance, tint, clamp and strength", "[bloom][model]") {
  const Picture input = scene(48, 40);
  const char* const settings[][3] = {
      {"bloom.knee=0.5", "bloom.threshold=1", "bloom.strength=2"},
      {"bloom.measure=luminance", "bloom.threshold=0.5", "bloom.knee=0.25"},
      {"bloom.tint=1,0.5,0.25", "bloom.strength=3", "bloom.levels=3"},
      {"bloom.firefly_clamp=4", "bloom.threshold=0", "bloom.levels=2"},
      {"bloom.threshold=0", "bloom.knee=3", "bloom.strength=0.5"}};  // knee limited to the threshold
  for (const char* mode : kModes)
    for (const auto& group : settings) {
      Rig fresh;
      fresh.set(std::string("bloom.mode=") + mode);
      for (const char* s : group) fresh.set(s);
      INFO(mode << ": " << group[0] << " " << group[1] << " " << group[2]);
      Rendered r = fresh.render(input);
      require_matches_model(r);
    }
}

TEST_CASE("the gaussian mode matches its model for every sigma, tap count, downscale and tone scale", "[bloom][model][gaussian]") {
  const Picture input = scene(70, 50);
  const char* const settings[][4] = {
      {"bloom.downscale=1", "bloom.sigma=2", "bloom.taps=13", "bloom.tone_scale=1"},
      {"bloom.downscale=2", "bloom.sigma=5", "bloom.taps=8", "bloom.tone_scale=0.7"},  // 8 -> 9 taps
      {"bloom.downscale=3", "bloom.sigma=9", "bloom.taps=21", "bloom.tone_scale=1"},
      {"bloom.downscale=8", "bloom.sigma=20", "bloom.taps=9", "bloom.tone_scale=0.5"},
      {"bloom.downscale=16", "bloom.sigma=0.5", "bloom.taps=1", "bloom.tone_scale=2"}};
  for (const auto& group : settings) {
    Rig rig;
    rig.set("bloom.mode=gaussian");
    for (const char* s : group) rig.set(s);
    INFO(group[0] << " " << group[1] << " " << group[2] << " " << group[3]);
    Rendered r = rig.render(input);
    REQUIRE(r.passes == 4);
    require_matches_model(r);
  }
}

TEST_CASE("the mgf mode matches its model for every ratio", "[bloom][model][mgf]") {
  const Picture input = scene(96, 64);
  for (const char* ratio : {"0.5", "1", "2", "4"}) {
    Rig rig;
    rig.set("bloom.mode=mgf");
    rig.set(std::string("bloom.mgf_ratio=") + ratio);
    INFO("mgf_ratio=" << ratio);
    require_matches_model(rig.render(input));
  }
}

TEST_CASE("the tolerance is tight enough to catch a 10% wrong strength in every mode", "[bloom][model]") {
  for (const char* mode : kModes) {
    INFO(mode);
    Rig rig, stronger;
    for (Rig* r : {&rig, &stronger}) {
      r->set(std::string("bloom.mode=") + mode);
      r->set("bloom.levels=3");
    }
    stronger.set("bloom.strength=1.1");
    Rendered r = rig.render(scene(64, 48));
    require_matches_model(r);
    Rendered wrong = stronger.render(scene(64, 48));
    CHECK(rms_error_ratio(r.output, wrong.model, r.input, r.trace, r.frame_scale) > 1.0);
  }
  Rig shallower;
  shallower.set("bloom.levels=2");
  Rig rig;
  rig.set("bloom.levels=3");
  Rendered r = rig.render(scene(64, 48)), fewer = shallower.render(scene(64, 48));
  CHECK(worst_error_ratio(r.output, fewer.model, r.trace) > 1.0);
  CHECK(rms_error_ratio(r.output, fewer.model, r.input, r.trace, r.frame_scale) > 1.0);
}

TEST_CASE("strength 0, a black tint or a zero clamp run no pass and leave the frame as it was", "[bloom][noop]") {
  for (const char* mode : kModes)
    for (const char* setting : {"bloom.strength=0", "bloom.tint=0", "bloom.firefly_clamp=0"}) {
      Rig rig;
      rig.set(std::string("bloom.mode=") + mode);
      rig.set(setting);
      Picture input = scene(16, 12);
      input.at(3, 4)[1] = std::nanf("");  // even a NaN is passed through untouched: nothing ran
      Rendered r = rig.render(input);
      INFO(mode << " " << setting);
      CHECK(r.passes == 0);
      CHECK(rig.chain().report().effects_skipped == std::vector<std::string>{"bloom"});
      CHECK(rig.chain().report().peak_target_bytes == 0);
      for (size_t i = 0; i < input.rgba.size(); ++i)
        REQUIRE((r.output.rgba[i] == r.input.rgba[i] || (std::isnan(r.output.rgba[i]) && std::isnan(r.input.rgba[i]))));
    }
}

TEST_CASE("gaussian with strength 0 but a tone scale runs the composite alone", "[bloom][noop][gaussian]") {
  Rig rig;
  rig.set("bloom.mode=gaussian");
  rig.set("bloom.strength=0");
  rig.set("bloom.tone_scale=0.5");
  Rendered r = rig.render(scene(16, 12));
  CHECK(r.passes == 1);
  require_matches_model(r);
  for (size_t i = 0; i < r.input.rgba.size(); ++i)
    REQUIRE(r.output.rgba[i] == (i % 4 == 3 ? r.input.rgba[i] : 0.5f * r.input.rgba[i]));
}

TEST_CASE("alpha passes through and the bloom only adds light", "[bloom]") {
  for (const char* mode : kModes) {
    Rig rig;
    rig.set(std::string("bloom.mode=") + mode);
    Picture input = scene(32, 24);
    for (int y = 0; y < input.height; ++y)
      for (int x = 0; x < input.width; ++x) input.at(x, y)[3] = float((x + y) % 5) / 4.0f;
    Rendered r = rig.render(input);
    INFO(mode);
    for (size_t i = 0; i < r.input.rgba.size(); ++i) {
      if (i % 4 == 3)
        REQUIRE(r.output.rgba[i] == r.input.rgba[i]);
      else
        REQUIRE(r.output.rgba[i] >= r.input.rgba[i]);
    }
  }
}

TEST_CASE("the light the GPU adds is the model's to within its half-float stores", "[bloom][model][energy]") {
  // Each of the S half-float stores on the way out rounds a value by at most 2^-10 of it, toward
  // zero where the renderer truncates (llvmpipe does on its stores): the light added may fall short
  // of the model's by up to S * 2^-10 and exceed it by no more than the output's own rounding.
  // docs/effects/bloom.md quotes the ratios (BLOOM_TEST_VERBOSE=1 prints them).
  const pfx::app::Image demo = pfx::app::make_demo_image(640, 360);
  Picture input;
  input.width = 640;
  input.height = 360;
  input.rgba = demo.rgba;  // row order does not matter for sums
  for (const char* mode : kModes) {
    Rig rig;
    rig.set(std::string("bloom.mode=") + mode);
    for (int levels : {1, 3, 6}) {
      rig.set("bloom.levels=" + std::to_string(levels));
      const Rendered r = rig.render(input);
      double gpu = 0, model = 0;
      for (size_t i = 0; i < r.output.rgba.size(); ++i)
        if (i % 4 != 3) gpu += double(r.output.rgba[i]) - r.input.rgba[i], model += double(r.model.rgba[i]) - r.input.rgba[i];
      if (std::getenv("BLOOM_TEST_VERBOSE"))
        std::fprintf(stderr, "light added, GPU / model: %s levels=%d (%d stores) %.4f\n", mode, r.levels, r.trace.stores,
                     gpu / model);
      INFO(mode << " levels=" << r.levels << ": GPU / model = " << gpu / model);
      CHECK(gpu / model >= 1.0 - r.trace.stores * std::ldexp(1.0, -10));
      CHECK(gpu / model <= 1.0 + std::ldexp(1.0, -10));
      if (std::string(mode) == "gaussian") break;  // one buffer whatever the levels
    }
  }
}
