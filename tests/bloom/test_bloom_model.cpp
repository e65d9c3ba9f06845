// The CPU model (PFX_REFERENCE_MODEL) on its own: the bright pass, energy, constant frames,
// and the handling of bad values, without a GPU.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "bloom_params.hpp"
#include "gaussian_taps.hpp"
#include "reference/bloom_model.hpp"

using pfx_bloom::Settings;

namespace {

struct Frame {
  int w, h;
  std::vector<float> rgba;
  Frame(int width, int height, float v) : w(width), h(height), rgba(size_t(width) * height * 4, v) {
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 1.0f;
  }
  float* at(int x, int y) { return &rgba[(size_t(y) * w + x) * 4]; }
};

std::vector<float> run(const Settings& s, const Frame& f) {
  std::vector<float> out(f.rgba.size());
  pfx_bloom::evaluate_model(s, f.w, f.h, f.rgba.data(), out.data());
  return out;
}

double added_energy(const Frame& f, const std::vector<float>& out) {
  double sum = 0;
  for (size_t i = 0; i < out.size(); ++i)
    if (i % 4 != 3) sum += double(out[i]) - double(f.rgba[i]);
  return sum;
}

Settings defaults() {
  pfx_value values[pfx_bloom::PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_bloom::PARAM_COUNT; ++i) values[i] = pfx_bloom::kParams[i].default_value;
  return pfx_bloom::settings_from(values);
}

}  // namespace

TEST_CASE("the defaults are the half-size chain with a threshold of 1 and a hard knee", "[bloom][model]") {
  const Settings s = defaults();
  CHECK(s.mode == pfx_bloom::MODE_CHAIN);
  CHECK(s.threshold == 1.0);
  CHECK(s.knee == 0.0);
  CHECK(s.measure == pfx_bloom::MEASURE_MAX_RGB);
  CHECK(s.firefly_clamp == 65472.0);
  CHECK(s.levels == 0);
}

TEST_CASE("a constant frame gains strength x its bright part away from the border", "[bloom][model]") {
  // The chain divides the strength by the level count because every level adds the same light.
  Settings s = defaults();
  s.levels = 3;
  s.strength = 2.0;
  Frame f(128, 128, 0.0f);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) f.at(x, y)[0] = 3.0f, f.at(x, y)[1] = 1.5f, f.at(x, y)[2] = 0.75f;
  const std::vector<float> out = run(s, f);
  // max(R,G,B) = 3, ratio (3 - 1) / 3: bright part (2, 1, 0.5), times strength 2.
  const float* centre = &out[(size_t(64) * 128 + 64) * 4];
  CHECK(centre[0] == Approx(3.0 + 4.0));
  CHECK(centre[1] == Approx(1.5 + 2.0));
  CHECK(centre[2] == Approx(0.75 + 1.0));
  // The border reads black going down: the corner gets less.
  CHECK(out[0] < centre[0]);
}

TEST_CASE("knee 0 is the plain threshold ratio, a knee makes it continuous and never adds light below zero", "[bloom][model]") {
  // A constant frame far from the border gains exactly strength x bright part (see above), so
  // its centre shows the bright-pass curve itself.
  auto gain_at = [](double knee, float r, float g) {
    pfx_value values[pfx_bloom::PARAM_COUNT];
    for (uint32_t i = 0; i < pfx_bloom::PARAM_COUNT; ++i) values[i] = pfx_bloom::kParams[i].default_value;
    values[pfx_bloom::PARAM_LEVELS].v[0] = 1;
    values[pfx_bloom::PARAM_THRESHOLD].v[0] = 2.0;
    values[pfx_bloom::PARAM_KNEE].v[0] = knee;
    const Settings s = pfx_bloom::settings_from(values);  // where the knee is limited
    Frame f(48, 48, 0.0f);
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x) f.at(x, y)[0] = r, f.at(x, y)[1] = g;
    const std::vector<float> out = run(s, f);
    const float* centre = &out[(size_t(24) * 48 + 24) * 4];
    return std::pair<double, double>{centre[0] - r, centre[1] - g};
  };
  // b = 5: ratio (5 - 2) / 5, with or without a knee of 1 (5 lies above threshold + knee).
  CHECK(gain_at(0.0, 5.0f, 1.0f).first == Approx(3.0));
  CHECK(gain_at(0.0, 5.0f, 1.0f).second == Approx(0.6));
  CHECK(gain_at(1.0, 5.0f, 1.0f).first == Approx(3.0));
  // At the threshold: the hard knee gives nothing, the soft one (0 + 1)^2 / (4 * 1) of b = 2.
  CHECK(gain_at(0.0, 2.0f, 0.0f).first == 0.0);
  CHECK(gain_at(1.0, 2.0f, 0.0f).first == Approx(0.25));
  // Below threshold - knee nothing; a knee wider than the threshold is limited to it.
  CHECK(gain_at(1.0, 0.99f, 0.0f).first == 0.0);
  CHECK(gain_at(50.0, 0.001f, 0.0f).first <= 0.001);
}

TEST_CASE("a single bright pixel spreads strength x its light, with or without levels", "[bloom][model]") {
  // Far from the border every stage keeps the light: the bright pass's 5 taps weigh 8/8, the
  // downsample's 16 weigh 1, the tent 1, each over a grid half as fine. So with threshold 0 the
  // bloom's energy is exactly strength x the frame's.
  Frame f(256, 256, 0.0f);
  f.at(130, 121)[0] = f.at(130, 121)[1] = f.at(130, 121)[2] = 11.0f;
  for (int levels = 1; levels <= 4; ++levels) {
    Settings s = defaults();
    s.levels = levels;
    s.strength = 1.5;
    s.threshold = 0.0;
    INFO(levels << " levels");
    CHECK(added_energy(f, run(s, f)) == Approx(1.5 * 3 * 11.0).epsilon(1e-6));
    // The bright pass thresholds the bilinear taps, not the pixels: a lone pixel is spread over the taps
    // first and loses more than the threshold to it (here 70% of strength x (11 - 1) is left).
    s.threshold = 1.0;
    const double kept = added_energy(f, run(s, f)) / (1.5 * 3 * 10.0);
    CHECK(kept == Approx(0.7).epsilon(1e-6));
  }
}

TEST_CASE("the model treats bad values as the shaders do", "[bloom][model]") {
  const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
  Settings s = defaults();
  s.levels = 2;
  Frame zeroed(32, 32, 0.5f), bad = zeroed;
  bad.at(9, 9)[0] = nan;
  bad.at(9, 9)[1] = -inf;
  bad.at(9, 9)[2] = -4.0f;
  bad.at(9, 9)[3] = nan;
  zeroed.at(9, 9)[0] = zeroed.at(9, 9)[1] = zeroed.at(9, 9)[2] = 0.0f;
  // nonfinite=clamp (the behaviour before the parameter existed): channel by channel, NaN -> 0 and
  // -Inf -> -65504, which adds no light but stays in the output.
  s.nonfinite = pfx_bloom::NONFINITE_CLAMP;
  std::vector<float> a = run(s, bad), b = run(s, zeroed);
  for (size_t i = 0; i < a.size(); ++i) {
    REQUIRE(std::isfinite(a[i]));
    if (i / 4 != size_t(9 * 32 + 9)) REQUIRE(a[i] == b[i]);
  }
  CHECK(a[(9 * 32 + 9) * 4 + 1] == Approx(-65504.0 + b[(9 * 32 + 9) * 4 + 1]));
  CHECK(a[(9 * 32 + 9) * 4 + 3] == 0.0f);

  // nonfinite=zero, the default: the whole pixel is black (its finite -4 too), alpha 0 since it is NaN.
  s.nonfinite = pfx_bloom::NONFINITE_ZERO;
  zeroed.at(9, 9)[3] = 0.0f;
  a = run(s, bad);
  b = run(s, zeroed);
  for (size_t i = 0; i < a.size(); ++i) REQUIRE(a[i] == b[i]);

  Frame hot(32, 32, 0.0f);
  hot.at(16, 16)[0] = inf;
  s.strength = 100;
  s.nonfinite = pfx_bloom::NONFINITE_CLAMP;
  const std::vector<float> clamped = run(s, hot);
  for (float v : clamped) REQUIRE(v <= 65504.0f);
  CHECK(clamped[(16 * 32 + 17) * 4] > 1000.0f);  // +Inf blooms as the firefly clamp
  s.nonfinite = pfx_bloom::NONFINITE_ZERO;
  const std::vector<float> dropped = run(s, hot);
  for (size_t i = 0; i < dropped.size(); ++i) REQUIRE(dropped[i] == (i % 4 == 3 ? 1.0f : 0.0f));  // no light at all
}

TEST_CASE("gaussian and mgf keep the light: a lone pixel adds exactly strength x its bright part", "[bloom][model]") {
  // Block averages, normalised Gaussians and bilinear upsampling all keep the light away from the
  // border when the blocks tile the frame (480 is a multiple of every downscale here); mgf's weights
  // sum to 1. Both take 11 - 1 = 10 of each channel.
  Frame f(480, 480, 0.0f);
  f.at(250, 241)[0] = f.at(250, 241)[1] = f.at(250, 241)[2] = 11.0f;
  Settings s = defaults();
  s.strength = 1.5;
  s.mode = pfx_bloom::MODE_GAUSSIAN;
  for (int downscale : {1, 2, 4, 5}) {
    s.downscale = downscale;
    INFO("downscale " << downscale);
    CHECK(added_energy(f, run(s, f)) == Approx(1.5 * 3 * 10.0).epsilon(1e-6));
  }
  s.mode = pfx_bloom::MODE_MGF;
  s.levels = 3;
  CHECK(added_energy(f, run(s, f)) == Approx(1.5 * 3 * 10.0).epsilon(1e-6));
}

TEST_CASE("the gaussian mode at full resolution is the discrete Gaussian of its sigma and taps", "[bloom][model][gaussian]") {
  // One pixel, downscale 1: the bloom at (dx, dy) is strength x bright x w[dx] x w[dy], with w the
  // normalised weights exp(-k^2 / 2 sigma^2) over the taps (computed here, not by the plugin).
  Frame f(64, 64, 0.0f);
  f.at(30, 33)[1] = 5.0f;  // green only: 4 above the threshold
  Settings s = defaults();
  s.mode = pfx_bloom::MODE_GAUSSIAN;
  s.downscale = 1;
  s.sigma = 3.0;
  s.half_taps = 6;
  std::vector<double> w(7);
  double sum = 0;
  for (int k = 0; k <= 6; ++k) sum += (k ? 2 : 1) * (w[k] = std::exp(-k * k / 18.0));
  const std::vector<float> out = run(s, f);
  for (int dy = -8; dy <= 8; ++dy)
    for (int dx = -8; dx <= 8; ++dx) {
      const double expected = std::abs(dx) <= 6 && std::abs(dy) <= 6 ? 4.0 * w[std::abs(dx)] * w[std::abs(dy)] / (sum * sum) : 0.0;
      const float* o = &out[(size_t(33 + dy) * 64 + 30 + dx) * 4];
      REQUIRE(o[1] - f.at(30 + dx, 33 + dy)[1] == Approx(expected).margin(1e-6));
      REQUIRE(o[0] == 0.0f);
    }
}

TEST_CASE("chain13's Karis average takes light from a lone bright pixel, none from a flat area", "[bloom][model]") {
  Settings s = defaults();
  s.mode = pfx_bloom::MODE_CHAIN13;
  s.threshold = 0.0;
  s.levels = 3;
  Frame lone(128, 128, 0.0f);
  lone.at(64, 60)[0] = lone.at(64, 60)[1] = lone.at(64, 60)[2] = 11.0f;
  const double kept = added_energy(lone, run(s, lone)) / (3 * 11.0);
  CHECK(kept < 0.5);  // the firefly is tamed
  Frame flat(128, 128, 2.0f);
  const std::vector<float> out = run(s, flat);
  CHECK(out[(size_t(64) * 128 + 64) * 4] == Approx(4.0));  // a constant keeps all of its light
}
