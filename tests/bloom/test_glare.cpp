// The glare effect (Kawase's star streaks): GPU against its CPU model over its parameters, and the
// model against the streak kernel computed here from Kawase's formula. The named hard cases run
// for glare in test_bloom_hard_cases.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "bloom_rig.hpp"
#include "glare_params.hpp"
#include "reference/glare_model.hpp"

using namespace bloom_test;

TEST_CASE("glare on the GPU matches its CPU model over streaks, angle, attenuation, resolution and tint", "[glare][model]") {
  const Picture input = scene(72, 54);
  const char* const settings[][3] = {
      {"streaks=4", "angle=45", "attenuation=0.925"},     {"streaks=6", "angle=0", "attenuation=0.9"},
      {"streaks=8", "angle=10", "attenuation=0.95"},      {"resolution=half", "streaks=6", "tint=1,0.5,0.2"},
      {"resolution=quarter", "angle=-30", "strength=3"},  {"threshold=0", "knee=0.5", "measure=luminance"}};
  for (const auto& group : settings) {
    Rig rig("glare");
    for (const char* s : group) rig.set(s);
    INFO(group[0] << " " << group[1] << " " << group[2]);
    const Rendered r = rig.render(input);
    require_matches_model(r);
  }
  for (auto [w, h] : {std::pair{37, 23}, std::pair{100, 7}}) {
    Rig rig("glare");
    require_matches_model(rig.render(scene(w, h)));
  }
}

TEST_CASE("glare: the tolerance catches a 10% wrong strength, and strength 0 runs no pass", "[glare][model]") {
  Rig rig("glare"), stronger("glare"), off("glare");
  stronger.set("strength=1.1");
  const Rendered r = rig.render(scene(64, 48)), wrong = stronger.render(scene(64, 48));
  require_matches_model(r);
  CHECK(rms_error_ratio(r.output, wrong.model, r.input, r.trace, 1.0) > 1.0);
  CHECK(r.passes == 14);
  off.set("strength=0");
  const Rendered none = off.render(scene(16, 12));
  CHECK(none.passes == 0);
  CHECK(off.chain().report().effects_skipped == std::vector<std::string>{"glare"});
  for (size_t i = 0; i < none.input.rgba.size(); ++i) REQUIRE(none.output.rgba[i] == none.input.rgba[i]);
}

namespace {

pfx_bloom::GlareSettings glare_defaults() {
  pfx_value values[pfx_bloom::GLARE_PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::GLARE_PARAM_COUNT; ++i) values[i] = pfx_bloom::kGlareParams[i].default_value;
  return pfx_bloom::glare_settings_from(values);
}

}  // namespace

TEST_CASE("glare's streaks are Kawase's three-pass kernel, weights a to the power b s with b = 1, 4, 16", "[glare][model]") {
  // Angle 0, four streaks: every tap lies on a texel, so each arm of the cross is exactly the 1-D
  // kernel K(t) = sum over s0 + 4 s1 + 16 s2 = t of w0(s0) w1(s1) w2(s2), w_i(s) = a^(4^i s) / sum,
  // a quarter of the light per arm; the light at p reaches p - t along each direction.
  pfx_bloom::GlareSettings g = glare_defaults();
  g.angle = 0.0;
  g.bright.threshold = 0.0;
  const int size = 400, px = 200, py = 190;
  std::vector<float> in(size_t(size) * size * 4, 0.0f), out(in.size());
  in[(size_t(py) * size + px) * 4 + 2] = 8.0f;  // blue only
  pfx_bloom::evaluate_glare_model(g, size, size, in.data(), out.data());
  std::vector<double> w[3];
  for (int i = 0; i < 3; ++i) {
    double sum = 0;
    for (int s = 0; s < 16; ++s) sum += std::pow(0.925, std::pow(4.0, i) * s);
    for (int s = 0; s < 16; ++s) w[i].push_back(std::pow(0.925, std::pow(4.0, i) * s) / sum);
  }
  std::vector<double> kernel(16 + 4 * 15 + 16 * 15, 0.0);
  for (int s0 = 0; s0 < 16; ++s0)
    for (int s1 = 0; s1 < 16; ++s1)
      for (int s2 = 0; s2 < 16; ++s2) kernel[size_t(s0 + 4 * s1 + 16 * s2)] += w[0][s0] * w[1][s1] * w[2][s2];
  auto added = [&](int x, int y) { return double(out[(size_t(y) * size + x) * 4 + 2]) - in[(size_t(y) * size + x) * 4 + 2]; };
  for (int t = 1; t < 180; ++t) {
    INFO("t = " << t);
    REQUIRE(added(px - t, py) == Approx(8.0 * kernel[t] / 4).margin(1e-6));
    REQUIRE(added(px + t, py) == Approx(8.0 * kernel[t] / 4).margin(1e-6));
    REQUIRE(added(px, py - t) == Approx(8.0 * kernel[t] / 4).margin(1e-6));
    REQUIRE(added(px + t, py + 1) == 0.0);  // nothing off the arms
  }
  CHECK(added(px, py) == Approx(8.0 * kernel[0]).margin(1e-6));  // the four arms' own tap 0
  // Energy: strength x the light above the threshold, spread over the streaks.
  double total = 0;
  for (size_t i = 2; i < out.size(); i += 4) total += double(out[i]) - in[i];
  CHECK(total == Approx(8.0).epsilon(1e-5));
}
