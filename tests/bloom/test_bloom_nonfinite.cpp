// A few bad pixels do not light the frame: NaN and +-Inf are a renderer's failed samples, and with
// nonfinite=zero (the default) they count as black before any filtering, in every mode and in
// glare; nonfinite=clamp keeps the earlier behaviour, where +Inf blooms as the brightest light the
// firefly clamp allows. And the Karis-weighted first downsample, an option of chain and mgf.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "bloom_rig.hpp"

using namespace bloom_test;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// scene()'s gradient and spots with rings of light around the middle (values 2 to 9, exact in half):
// bright, structured content for bad pixels to sit in.
Picture rings(int w, int h) {
  Picture p = scene(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double r = std::hypot(x - w / 2.0, y - h / 2.0);
      const int ring = static_cast<int>(r) / 6;
      if (ring % 3 == 0 && ring < 12) {
        float* c = p.at(x, y);
        c[0] = c[1] = c[2] = 2.0f + static_cast<float>(ring % 8);
      }
    }
  return p;
}

const int kBad[4][2] = {{37, 41}, {120, 30}, {71, 100}, {160, 121}};

// Pixels (of any channel, alpha too) where a and b differ.
int changed_pixels(const Picture& a, const Picture& b) {
  int changed = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (int c = 0; c < 4; ++c)
      if (a.rgba[i + c] != b.rgba[i + c]) {
        ++changed;
        break;
      }
  return changed;
}

// The bloom modes and glare, and the Karis options.
const char* const kSettings[][2] = {{"chain", ""},   {"chain13", ""},       {"gaussian", ""}, {"mgf", ""},
                                    {"glare", ""},   {"chain", "karis=1"}, {"mgf", "karis=1"}};

}  // namespace

// The documented neighbourhood of a bad pixel with nonfinite=zero is nothing: the output is, bit for
// bit, that of the same frame with those pixels black. Before the parameter (nonfinite=clamp) four
// +Inf pixels lit most of the frame.
TEST_CASE("4 +Inf, NaN or -Inf pixels change nothing but themselves with nonfinite=zero, in every mode",
          "[bloom][hard][nonfinite]") {
  const Picture base = rings(200, 150);
  Picture black = base;
  for (const auto& p : kBad)
    for (int c = 0; c < 3; ++c) black.at(p[0], p[1])[c] = 0.0f;
  for (const auto& setting : kSettings) {
    Rig rig = rig_for(setting[0]);
    if (*setting[1]) rig.set(setting[1]);
    const Rendered reference = rig.render(black);
    for (float bad : {kInf, std::nanf(""), -kInf}) {
      Picture input = base;
      for (const auto& p : kBad)
        for (int c = 0; c < 3; ++c) input.at(p[0], p[1])[c] = bad;
      INFO(setting[0] << " " << setting[1] << " with " << bad);
      const Rendered r = rig.render(input);
      require_matches_model(r);
      CHECK(changed_pixels(r.output, reference.output) == 0);
    }
  }
}

TEST_CASE("nonfinite=clamp keeps the earlier behaviour: 4 +Inf pixels bloom as the firefly clamp", "[bloom][hard][nonfinite]") {
  const Picture base = rings(200, 150);
  Picture black = base, with_inf = base;
  for (const auto& p : kBad)
    for (int c = 0; c < 3; ++c) black.at(p[0], p[1])[c] = 0.0f, with_inf.at(p[0], p[1])[c] = kInf;
  for (const auto& setting : kSettings) {
    Rig rig = rig_for(setting[0]);
    rig.set("nonfinite=clamp");
    if (*setting[1]) rig.set(setting[1]);
    const Rendered r = rig.render(with_inf), reference = rig.render(black);
    INFO(setting[0] << " " << setting[1]);
    require_matches_model(r);
    const int changed = changed_pixels(r.output, reference.output);
    if (std::getenv("BLOOM_TEST_VERBOSE"))
      std::fprintf(stderr, "nonfinite=clamp %s %s: 4 +Inf pixels change %d of %d pixels\n", setting[0], setting[1], changed,
                   200 * 150);
    CHECK(changed > 1000);  // far beyond the four: each carries 65472 into every level
    CHECK(r.output.at(kBad[0][0], kBad[0][1])[0] == 65504.0f);
  }
}

TEST_CASE("karis: chain and mgf with the Karis-weighted first downsample match their models", "[bloom][model][karis]") {
  for (const char* mode : {"chain", "mgf"}) {
    Rig rig = rig_for(mode);
    rig.set("karis=1");
    for (auto [w, h] : {std::pair{96, 64}, std::pair{37, 23}}) {
      INFO(mode << " " << w << "x" << h);
      require_matches_model(rig.render(scene(w, h)));
    }
  }
}

TEST_CASE("karis: a lone firefly gives up most of its light, a broad highlight keeps it", "[bloom][model][karis]") {
  // One pixel of 1000 on black: in its block (mgf: 16 pixels) or among its taps (chain: 5) it weighs
  // 1 / (1 + 999) against 1 for each black one, so it keeps about 1 / 15 (mgf) of what the plain
  // average gives it. A flat area of 2 has equal weights everywhere but where a downsample's taps
  // reach past the frame's edge (black, weighted 1 against 1 / 2): it keeps nearly all.
  for (const char* mode : {"chain", "mgf"}) {
    Rig plain = rig_for(mode), karis = rig_for(mode);
    karis.set("karis=1");
    Picture firefly(64, 64, 0, 0, 0);
    firefly.at(30, 33)[0] = firefly.at(30, 33)[1] = firefly.at(30, 33)[2] = 1000.0f;
    auto added = [](const Rendered& r) {
      double sum = 0;
      for (size_t i = 0; i < r.model.rgba.size(); ++i)
        if (i % 4 != 3) sum += double(r.output.rgba[i]) - r.input.rgba[i];
      return sum;
    };
    INFO(mode);
    const double lone_plain = added(plain.render(firefly)), lone_karis = added(karis.render(firefly));
    CHECK(lone_karis < 0.2 * lone_plain);
    CHECK(lone_karis > 0.0);
    Picture flat(64, 64, 2.0f, 2.0f, 2.0f);
    const Rendered a = plain.render(flat), b = karis.render(flat);
    require_matches_model(b);
    CHECK(added(b) > 0.97 * added(a));
    CHECK(added(b) <= added(a));
  }
}
