// Energy: the total added light against strength x thresholded energy, for every
// bloom mode, its ideal, and glare, on the demo frame through the CPU references (which the GPU
// matches within the stated tolerance). docs/effects/bloom.md quotes the figures
// (BLOOM_TEST_VERBOSE=1 prints them).
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bloom_params.hpp"
#include "demo_image.hpp"
#include "glare_params.hpp"
#include "reference/bloom_model.hpp"
#include "reference/glare_model.hpp"
#include "reference/ideal.hpp"
#include "reference/model_common.hpp"

namespace {

constexpr int kW = 640, kH = 360;

// strength x the light above the threshold, pixel by pixel, under the mode's measure.
double thresholded_light(const pfx_bloom::Settings& s, int measure, const std::vector<float>& frame) {
  const pfx_bloom::model::Plane safe = pfx_bloom::model::safe_frame(frame.data(), kW, kH, s.firefly_clamp, s.nonfinite);
  double sum = 0;
  for (size_t i = 0; i < safe.rgb.size(); i += 3) {
    double c[3] = {safe.rgb[i], safe.rgb[i + 1], safe.rgb[i + 2]};
    pfx_bloom::model::bright_part(s, measure, c);
    sum += c[0] + c[1] + c[2];
  }
  return s.strength * sum;
}

double added_light(const std::vector<float>& frame, const std::vector<float>& out) {
  double sum = 0;
  for (size_t i = 0; i < out.size(); ++i)
    if (i % 4 != 3) sum += double(out[i]) - frame[i];
  return sum;
}

pfx_bloom::Settings bloom_settings(int mode) {
  pfx_value values[pfx_bloom::PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::PARAM_COUNT; ++i) values[i] = pfx_bloom::kParams[i].default_value;
  values[pfx_bloom::PARAM_MODE].v[0] = mode;
  return pfx_bloom::settings_from(values);
}

void report(const char* what, double ratio) {
  if (std::getenv("BLOOM_TEST_VERBOSE")) std::fprintf(stderr, "energy %-16s %.4f\n", what, ratio);
}

}  // namespace

TEST_CASE("energy: the light each mode adds against strength x the thresholded light of the demo frame", "[bloom][energy]") {
  const pfx::app::Image demo = pfx::app::make_demo_image(kW, kH);
  const std::vector<float> frame = demo.rgba;  // row order does not matter for sums
  std::vector<float> out(frame.size());
  double ratio[pfx_bloom::MODE_COUNT], ideal[pfx_bloom::MODE_COUNT];
  for (int mode = 0; mode < pfx_bloom::MODE_COUNT; ++mode) {
    const pfx_bloom::Settings s = bloom_settings(mode);
    const int measure = mode == pfx_bloom::MODE_GAUSSIAN ? pfx_bloom::model::kMeasurePerChannel : s.measure;
    const double expected = thresholded_light(s, measure, frame);
    REQUIRE(expected > 0);
    pfx_bloom::evaluate_model(s, kW, kH, frame.data(), out.data());
    ratio[mode] = added_light(frame, out) / expected;
    pfx_bloom::evaluate_ideal(s, kW, kH, frame.data(), out.data());
    ideal[mode] = added_light(frame, out) / expected;
    report(pfx_bloom::mode_name(mode), ratio[mode]);
    report((std::string(pfx_bloom::mode_name(mode)) + " ideal").c_str(), ideal[mode]);
    INFO(pfx_bloom::mode_name(mode) << ": " << ratio[mode] << ", its ideal " << ideal[mode]);
    // The ideals keep all of it but what spreads past the frame's edge.
    CHECK(ideal[mode] > 0.85);
    CHECK(ideal[mode] <= 1.0);
  }
  // gaussian and mgf lose only what the border takes, as their ideals do.
  CHECK(ratio[pfx_bloom::MODE_GAUSSIAN] == Approx(ideal[pfx_bloom::MODE_GAUSSIAN]).epsilon(0.02));
  CHECK(ratio[pfx_bloom::MODE_MGF] == Approx(ideal[pfx_bloom::MODE_MGF]).epsilon(0.05));
  // The chain thresholds filtered taps, which on the demo's broad highlights costs almost nothing
  // (a lone pixel loses more: test_bloom_model.cpp); chain13's Karis average gives up half of the
  // light of the demo's small, very bright spots, by design.
  CHECK(ratio[pfx_bloom::MODE_CHAIN] == Approx(ideal[pfx_bloom::MODE_CHAIN]).epsilon(0.01));
  CHECK(ratio[pfx_bloom::MODE_CHAIN13] < 0.8 * ratio[pfx_bloom::MODE_CHAIN]);

  pfx_value values[pfx_bloom::GLARE_PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::GLARE_PARAM_COUNT; ++i) values[i] = pfx_bloom::kGlareParams[i].default_value;
  values[pfx_bloom::GLARE_RESOLUTION].v[0] = 1;  // half: the model at full size is slow
  const pfx_bloom::GlareSettings g = pfx_bloom::glare_settings_from(values);
  pfx_bloom::evaluate_glare_model(g, kW, kH, frame.data(), out.data());
  const double glare = added_light(frame, out) / thresholded_light(g.bright, g.bright.measure, frame);
  report("glare (half)", glare);
  CHECK(glare > 0.7);  // long streaks leave the frame
  CHECK(glare <= 1.0);
}
