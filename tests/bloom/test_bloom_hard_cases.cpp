// The named hard cases, each for every bloom mode and for glare: bad values in the frame (NaN, +-Inf, above
// the half-float maximum, negative), tiny and odd sizes, and settings at their edges.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "bloom_levels.hpp"
#include "gaussian_taps.hpp"
#include "bloom_rig.hpp"

using namespace bloom_test;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Pixels where the model's output changes when pixel (px, py) goes from 0 to the brightest value
// the bright pass lets through: how far one pixel can reach with these settings. Grown by one pixel
// for the GPU's coordinate rounding.
std::vector<bool> reach_of(Rig& rig, const Picture& base, int px, int py) {
  Picture zero = base, bright = base;
  float* z = zero.at(px, py);
  float* b = bright.at(px, py);
  for (int c = 0; c < 3; ++c) z[c] = 0.0f, b[c] = 65472.0f;
  const Rendered rz = rig.render(zero), rb = rig.render(bright);
  const int w = base.width, h = base.height;
  std::vector<bool> changed(size_t(w) * h, false), reach(size_t(w) * h, false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x == px && y == py) continue;  // the pixel itself changes anyway
      for (int c = 0; c < 3; ++c)
        if (rz.model.at(x, y)[c] != rb.model.at(x, y)[c]) changed[size_t(y) * w + x] = true;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int sx = x + dx, sy = y + dy;
          if (sx >= 0 && sy >= 0 && sx < w && sy < h && changed[size_t(sy) * w + sx]) reach[size_t(y) * w + x] = true;
        }
  return reach;
}

// The number of pixels, besides (px, py), where a and b differ, and how many of them lie outside reach.
std::pair<int, int> differences(const Picture& a, const Picture& b, const std::vector<bool>& reach, int px, int py) {
  int inside = 0, outside = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (x == px && y == py) continue;
      bool differs = false;
      for (int c = 0; c < 4; ++c) differs |= a.at(x, y)[c] != b.at(x, y)[c];
      if (differs) ++(reach[size_t(y) * a.width + x] ? inside : outside);
    }
  return {inside, outside};
}

}  // namespace

TEST_CASE("a NaN pixel contributes nothing: the output is that of the pixel zeroed, everywhere", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("threshold=0.5");
    Picture zeroed = scene(40, 30);
    zeroed.at(20, 15)[0] = zeroed.at(20, 15)[1] = zeroed.at(20, 15)[2] = 0.0f;
    Picture with_nan = zeroed;
    for (int c = 0; c < 4; ++c) with_nan.at(20, 15)[c] = std::nanf("");
    const Rendered a = rig.render(with_nan), b = rig.render(zeroed);
    REQUIRE(std::isnan(a.input.at(20, 15)[0]));  // the GPU really held a NaN
    REQUIRE(all_finite(a.output));
    require_matches_model(a);
    CHECK(a.output.at(20, 15)[3] == 0.0f);  // alpha, too, is made finite
    for (size_t i = 0; i < a.output.rgba.size(); ++i)
      if (i / 4 != size_t(15 * 40 + 20) || i % 4 != 3) REQUIRE(a.output.rgba[i] == b.output.rgba[i]);
  }
}

TEST_CASE("a single NaN pixel does not spread beyond the kernel's reach", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    if (rig.effect() == "bloom") rig.set("levels=2");
    const Picture base = scene(160, 120);
    const std::vector<bool> reach = reach_of(rig, base, 100, 70);
    Picture zeroed = base, with_nan = base;
    for (int c = 0; c < 3; ++c) zeroed.at(100, 70)[c] = 0.0f, with_nan.at(100, 70)[c] = std::nanf("");
    const Rendered a = rig.render(with_nan), b = rig.render(zeroed);
    REQUIRE(all_finite(a.output));
    const auto [inside, outside] = differences(a.output, b.output, reach, 100, 70);
    CHECK(outside == 0);
    CHECK(inside == 0);  // NaN counts as black, so it changes nothing at all
  }
}

TEST_CASE("nonfinite=clamp: a +Inf pixel is clamped before any target is written and reaches no further than the kernel",
          "[bloom][hard][nonfinite]") {
  // The behaviour before the nonfinite parameter, kept as its clamp setting.
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("nonfinite=clamp");
    if (rig.effect() == "bloom") rig.set("levels=2");
    const Picture base = scene(160, 120);
    const std::vector<bool> reach = reach_of(rig, base, 100, 70);
    Picture zeroed = base, with_inf = base;
    for (int c = 0; c < 3; ++c) zeroed.at(100, 70)[c] = 0.0f, with_inf.at(100, 70)[c] = kInf;
    const Rendered a = rig.render(with_inf), b = rig.render(zeroed);
    REQUIRE(std::isinf(a.input.at(100, 70)[0]));
    REQUIRE(all_finite(a.output));
    require_matches_model(a);
    CHECK(a.output.at(100, 70)[0] == 65504.0f);
    const auto [inside, outside] = differences(a.output, b.output, reach, 100, 70);
    CHECK(outside == 0);
    CHECK(inside > 0);  // it does bloom, as the clamp's value
  }
}

TEST_CASE("a +Inf pixel is black by default: the output is that of the pixel zeroed, everywhere", "[bloom][hard][nonfinite]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    Picture zeroed = scene(40, 30), with_inf = zeroed;
    // One channel is enough: a renderer's sample with an infinite channel is dropped whole.
    with_inf.at(20, 15)[1] = kInf;
    for (int c = 0; c < 3; ++c) zeroed.at(20, 15)[c] = 0.0f;
    const Rendered a = rig.render(with_inf), b = rig.render(zeroed);
    REQUIRE(std::isinf(a.input.at(20, 15)[1]));
    require_matches_model(a);
    for (size_t i = 0; i < a.output.rgba.size(); ++i) REQUIRE(a.output.rgba[i] == b.output.rgba[i]);
  }
}

TEST_CASE("nonfinite=clamp: a -Inf pixel becomes -65504 there and adds no light", "[bloom][hard][nonfinite]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("nonfinite=clamp");
    Picture zeroed = scene(24, 16), with_inf = zeroed;
    for (int c = 0; c < 3; ++c) zeroed.at(5, 5)[c] = 0.0f, with_inf.at(5, 5)[c] = -kInf;
    const Rendered a = rig.render(with_inf), b = rig.render(zeroed);
    REQUIRE(all_finite(a.output));
    require_matches_model(a);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 24; ++x)
        for (int c = 0; c < 3; ++c) {
          if (x == 5 && y == 5) continue;
          REQUIRE(a.output.at(x, y)[c] == b.output.at(x, y)[c]);
        }
    // -65504 plus the neighbours' bloom, rounded to half (32 apart there).
    CHECK(a.output.at(5, 5)[0] == Approx(-65504.0f + b.output.at(5, 5)[0]).margin(32));
  }
}

TEST_CASE("a -Inf pixel is black by default, in the output too", "[bloom][hard][nonfinite]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    Picture zeroed = scene(24, 16), with_inf = zeroed;
    with_inf.at(5, 5)[2] = -kInf;
    for (int c = 0; c < 3; ++c) zeroed.at(5, 5)[c] = 0.0f;
    const Rendered a = rig.render(with_inf), b = rig.render(zeroed);
    require_matches_model(a);
    for (size_t i = 0; i < a.output.rgba.size(); ++i) REQUIRE(a.output.rgba[i] == b.output.rgba[i]);
  }
}

TEST_CASE("a 70000 pixel (above the half-float maximum) gives a finite output", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    Picture input = scene(32, 24);
    for (int c = 0; c < 3; ++c) input.at(10, 12)[c] = 70000.0f;
    const Rendered r = rig.render(input);
    // The upload to RGBA16F already overflowed it (to +Inf, or to 65504 on a GL that saturates).
    CHECK(r.input.at(10, 12)[0] >= 65504.0f);
    REQUIRE(all_finite(r.output));
    require_matches_model(r);
    for (float v : r.output.rgba) REQUIRE(v <= 65504.0f);
  }
}

TEST_CASE("strength 100 on a frame of 65472 everywhere does not overflow the levels", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("strength=100");
    rig.set("threshold=0");
    const Rendered r = rig.render(Picture(20, 12, 65472.0f, 65472.0f, 65472.0f));
    REQUIRE(all_finite(r.output));
    require_matches_model(r);
  }
}

TEST_CASE("negative colours contribute no light", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("threshold=0");
    Picture zeroed = scene(24, 16), negative = zeroed;
    const float v[3] = {-50.0f, -3.0f, -0.5f};
    for (int c = 0; c < 3; ++c) zeroed.at(7, 9)[c] = 0.0f, negative.at(7, 9)[c] = v[c];
    const Rendered a = rig.render(negative), b = rig.render(zeroed);
    require_matches_model(a);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 24; ++x)
        for (int c = 0; c < 3; ++c) {
          if (x == 7 && y == 9)  // the pixel keeps its own (negative) colour plus its neighbours' bloom
            REQUIRE(a.output.at(x, y)[c] == Approx(b.output.at(x, y)[c] + v[c]).epsilon(1.0 / 512));
          else
            REQUIRE(a.output.at(x, y)[c] == b.output.at(x, y)[c]);
        }
    // A frame of nothing but negative colour is returned as it came.
    const Rendered all = rig.render(Picture(9, 7, -2.0f, -0.25f, -8.0f));
    for (size_t i = 0; i < all.input.rgba.size(); ++i) REQUIRE(all.output.rgba[i] == all.input.rgba[i]);
  }
}

TEST_CASE("1x1: one 1x1 level, the light the border does not take is added", "[bloom][hard][size]") {
  // Bright part b = (8,4,2) * (8 - 1) / 8 (max-RGB; gaussian: per channel (7, 3, 1)).
  // chain: the four corner taps read the border, so level 0 holds half of it (4 of the 8 weights),
  // and the tent over a 1x1 level is that texel. chain13: only the centre tap sees the pixel; it is
  // one of four taps in each corner box, whose Karis weights are 1 / (1 + luma(b)) against 1 for
  // the three black taps. gaussian (downscale 4), mgf (block 4): the one pixel is 1 of the 16 of
  // its block, and the blurs' side taps read the border: w0^2 of it stays. glare (full
  // resolution): every streak's three passes keep only their tap 0, weighted 1 / sum_s a^(b*s).
  double w[8];
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    const Rendered r = rig.render(Picture(1, 1, 8.0f, 4.0f, 2.0f));
    if (rig.effect() == "bloom") CHECK(r.levels == 1);
    require_matches_model(r);
    const std::string m = mode;
    double expected[3] = {3.5, 1.75, 0.875};
    if (m == "chain13") {
      const double karis = 1.0 / (1.0 + 0.2126 * 7.0 + 0.7152 * 3.5 + 0.0722 * 1.75);
      for (double& e : expected) e *= 2.0 * 0.125 * 4.0 * karis / (karis + 3.0);
    } else if (m == "gaussian" || m == "mgf") {
      pfx_bloom::gaussian_weights(m == "mgf" ? 2.5 : std::sqrt(64.0 - 15.0 / 4.0) / 4.0, 7, w);
      const double bright[3] = {7.0, m == "mgf" ? 3.5 : 3.0, m == "mgf" ? 1.75 : 1.0};
      for (int c = 0; c < 3; ++c) expected[c] = bright[c] / 16.0 * w[0] * w[0];
    } else if (m == "glare") {
      double kept = 1;
      for (double b : {1.0, 4.0, 16.0}) {
        double sum = 0;
        for (int t = 0; t < 16; ++t) sum += std::pow(0.925, b * t);
        kept /= sum;
      }
      for (double& e : expected) e *= 2.0 * kept;
    }
    CHECK(r.output.at(0, 0)[0] == Approx(8.0 + expected[0]).epsilon(1.0 / 512));
    CHECK(r.output.at(0, 0)[1] == Approx(4.0 + expected[1]).epsilon(1.0 / 512));
    CHECK(r.output.at(0, 0)[2] == Approx(2.0 + expected[2]).epsilon(1.0 / 512));
  }
}

TEST_CASE("2x3 and other odd sizes match the model", "[bloom][hard][size]") {
  for (const char* mode : kVariants) {
    Rig rig = rig_for(mode);
    rig.set("threshold=0.25");
    for (auto [w, h] : {std::pair{2, 3}, std::pair{3, 2}, std::pair{5, 1}, std::pair{1, 9}, std::pair{33, 17}}) {
      Picture input = scene(w, h);
      input.at(w / 2, h / 2)[0] = 20.0f;
      const Rendered r = rig.render(input);
      INFO(mode << " " << w << "x" << h);
      require_matches_model(r);
    }
  }
}

TEST_CASE("1917x1079: levels are clamped to what the size allows and the output matches the model", "[bloom][hard][size]") {
  const Picture input = scene(1917, 1079);
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    if (rig.effect() == "bloom") rig.set("levels=16");
    if (rig.effect() == "glare") rig.set("resolution=quarter");  // its model at full size takes 20 s
    const Rendered r = rig.render(input);
    const std::string m = mode;
    if (m == "chain" || m == "chain13") {
      CHECK(r.levels == 10);  // 958x539 ... 3x2, 1x1
      CHECK(r.passes == 20);
    } else if (m == "mgf") {
      CHECK(r.levels == 9);  // 479x269 ... 3x2, 1x1
      CHECK(r.passes == 20);
    } else if (m == "glare") {
      CHECK(r.passes == 14);  // bright, 4 streaks x 3, composite
    }
    require_matches_model(r);
  }
}

TEST_CASE("a threshold above every pixel leaves the frame exactly as it was", "[bloom][hard]") {
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    rig.set("threshold=100");  // the scene's brightest pixel is 40
    const Rendered r = rig.render(scene(30, 20));
    CHECK(r.passes > 0);  // not a no-op by its settings: the passes run and add exact zeros
    REQUIRE(all_finite(r.output));
    for (size_t i = 0; i < r.input.rgba.size(); ++i) REQUIRE(r.output.rgba[i] == r.input.rgba[i]);
  }
}

TEST_CASE("4096x16: levels down to 1x1 match the model", "[bloom][hard][size]") {
  const Picture input = scene(4096, 16);
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    if (rig.effect() == "bloom") rig.set("levels=16");
    const Rendered r = rig.render(input);
    const std::string m = mode;
    if (m == "chain" || m == "chain13") CHECK(r.levels == 12);  // 2048x8, 1024x4, 512x2, 256x1 ... 1x1
    if (m == "mgf") CHECK(r.levels == 11);                       // 1024x4, 512x2, 256x1 ... 1x1
    require_matches_model(r);
  }
}

TEST_CASE("a constant frame stays constant in the interior and darkens toward the border", "[bloom][hard][edges]") {
  // Threshold 0, strength 1: the interior gains exactly its own value (docs/effects/bloom.md has
  // the border figures). Each mode is set to reach about 12 pixels (mgf: 40; glare's weights fall
  // below 1e-5 of the light within about 150), so the middle of the frame is interior.
  const struct {
    const char* mode;
    const char* settings;
    int w, h, margin;
  } cases[] = {{"chain", "bloom.levels=2", 64, 48, 16},
               {"chain13", "bloom.levels=2", 64, 48, 16},
               {"gaussian", "bloom.sigma=3", 64, 48, 16},
               {"mgf", "bloom.levels=1", 128, 96, 44},
               {"glare", "glare.streaks=4", 320, 320, 150}};
  for (const auto& c : cases) {
    INFO(c.mode);
    Rig rig = rig_for(c.mode);
    rig.set("threshold=0");
    rig.set(c.settings);
    const Rendered r = rig.render(Picture(c.w, c.h, 0.5f, 0.25f, 2.0f));
    require_matches_model(r);
    for (int y = c.margin; y < c.h - c.margin; ++y)
      for (int x = c.margin; x < c.w - c.margin; ++x) {
        REQUIRE(r.output.at(x, y)[0] == Approx(1.0).epsilon(1.0 / 256));
        REQUIRE(r.output.at(x, y)[1] == Approx(0.5).epsilon(1.0 / 256));
        REQUIRE(r.output.at(x, y)[2] == Approx(4.0).epsilon(1.0 / 256));
      }
    CHECK(r.output.at(0, 0)[2] < r.output.at(0, c.h / 2)[2]);
    CHECK(r.output.at(0, c.h / 2)[2] < 3.9f);
  }
}

namespace {

// The float a half-float bit pattern stands for (every pattern, NaNs and denormals included).
float half_to_float(uint16_t h) {
  const int sign = (h >> 15) ? -1 : 1, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  if (exponent == 0x1f) return mantissa ? std::nanf("") : sign * kInf;
  if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
  return sign * std::ldexp(float(mantissa | 0x400), exponent - 25);
}

}  // namespace

TEST_CASE("a frame holding every half-float value gives a finite output that matches the model", "[bloom][hard]") {
  // 256x256 RGBA: every bit pattern four times (40503 is odd, so i * 40503 mod 2^16 runs through
  // them all), NaNs, +-Inf, denormals, +-65504 and -0 among them.
  Picture input(256, 256, 0, 0, 0);
  for (size_t i = 0; i < input.rgba.size(); ++i) input.rgba[i] = half_to_float(uint16_t((i * 40503u) & 0xffffu));
  for (const char* mode : kVariants) {
    INFO(mode);
    Rig rig = rig_for(mode);
    const Rendered r = rig.render(input);
    REQUIRE(all_finite(r.output));
    require_matches_model(r);
  }
}
