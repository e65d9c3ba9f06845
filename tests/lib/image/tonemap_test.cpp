#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "tonemap.hpp"

using pfx::app::ToneCurve;
using pfx::app::ToneMapSettings;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

std::array<int, 3> map(float r, float g, float b, ToneCurve curve = ToneCurve::Linear,
                       double ev = 0.0) {
  const float rgb[3] = {r, g, b};
  std::uint8_t out[3];
  ToneMapSettings s;
  s.curve = curve;
  s.exposure_ev = ev;
  pfx::app::tonemap_pixel(rgb, s, out);
  return {out[0], out[1], out[2]};
}

}  // namespace

TEST_CASE("tonemap linear: 0 -> 0, 1 -> 255, 0.5 -> 188 (sRGB)", "[image][tonemap]") {
  CHECK(map(0.0f, 1.0f, 0.5f) == std::array<int, 3>{0, 255, 188});
  // Above 1 clamps to white with the linear curve.
  CHECK(map(4.0f, 1.0001f, 1e30f) == std::array<int, 3>{255, 255, 255});
  // The linear toe of the sRGB curve: 0.001 * 12.92 * 255 = 3.29 -> 3.
  CHECK(map(0.001f, 0.0031308f, 0.18f) == std::array<int, 3>{3, 10, 118});
}

TEST_CASE("tonemap NaN pixels are magenta, +inf white, negatives black", "[image][tonemap]") {
  const float nan = std::nanf("");
  CHECK(map(nan, 0.5f, 0.5f) == std::array<int, 3>{255, 0, 255});
  CHECK(map(0.2f, 0.2f, nan, ToneCurve::Aces) == std::array<int, 3>{255, 0, 255});
  for (ToneCurve c : {ToneCurve::Linear, ToneCurve::Reinhard, ToneCurve::Aces}) {
    INFO(pfx::app::tone_curve_name(c));
    CHECK(map(kInf, -1.0f, -kInf, c) == std::array<int, 3>{255, 0, 0});
    CHECK(map(kInf, kInf, kInf, c, -100.0) == std::array<int, 3>{255, 255, 255});
    CHECK(map(0.0f, 0.0f, 0.0f, c, 1000.0) == std::array<int, 3>{0, 0, 0});
    // Huge finite values reach white without going through inf/inf.
    CHECK(map(3e38f, 1e20f, 65504.0f, c)[0] >= 254);
  }
}

TEST_CASE("tonemap exposure multiplies by 2^EV before the curve", "[image][tonemap]") {
  CHECK(map(0.25f, 0.25f, 0.25f, ToneCurve::Linear, 1.0) == map(0.5f, 0.5f, 0.5f));
  CHECK(map(1.0f, 1.0f, 1.0f, ToneCurve::Linear, -1.0) == map(0.5f, 0.5f, 0.5f));
}

TEST_CASE("tonemap curves: reinhard x/(1+x), aces fit, all monotonic into [0,1]",
          "[image][tonemap]") {
  // reinhard(1) = 0.5 -> the same code as linear 0.5.
  CHECK(map(1.0f, 1.0f, 1.0f, ToneCurve::Reinhard) == std::array<int, 3>{188, 188, 188});
  CHECK(pfx::app::apply_tone_curve(ToneCurve::Reinhard, 3.0f) == Approx(0.75f));
  // aces(1) = 2.54 / 3.16.
  CHECK(pfx::app::apply_tone_curve(ToneCurve::Aces, 1.0f) == Approx(2.54 / 3.16));
  CHECK(pfx::app::apply_tone_curve(ToneCurve::Aces, 0.0f) == 0.0f);
  for (ToneCurve c : {ToneCurve::Linear, ToneCurve::Reinhard, ToneCurve::Aces}) {
    float prev = 0.0f;
    for (float x = 0.0f; x < 1000.0f; x = x * 1.1f + 0.001f) {
      const float y = pfx::app::apply_tone_curve(c, x);
      CHECK(y >= prev);
      CHECK(y <= 1.0f);
      prev = y;
    }
  }
}

TEST_CASE("tonemap sRGB OETF matches the standard's breakpoints", "[image][tonemap]") {
  CHECK(pfx::app::srgb_oetf(0.0) == 0.0);
  CHECK(pfx::app::srgb_oetf(1.0) == Approx(1.0));
  CHECK(pfx::app::srgb_oetf(0.5) == Approx(0.735356983));
  CHECK(pfx::app::srgb_oetf(0.0031308) == Approx(0.04045).epsilon(1e-4));
  CHECK(pfx::app::encode_srgb8(0.5f) == 188);
  CHECK(pfx::app::encode_srgb8(2.0f) == 255);
  CHECK(pfx::app::encode_srgb8(-1.0f) == 0);
}

TEST_CASE("tonemap curve names parse, and a wrong name lists the valid ones",
          "[image][tonemap]") {
  REQUIRE(pfx::app::tone_curve_names().size() >= 3);
  for (const std::string& name : pfx::app::tone_curve_names()) {
    ToneCurve c{};
    std::string error;
    REQUIRE(pfx::app::parse_tone_curve(name, &c, &error));
    CHECK(pfx::app::tone_curve_name(c) == name);
    CHECK_THAT(pfx::app::tone_curve_help(), Catch::Contains(name));
  }
  ToneCurve c = ToneCurve::Aces;
  std::string error;
  CHECK_FALSE(pfx::app::parse_tone_curve("filmic", &c, &error));
  CHECK(c == ToneCurve::Aces);
  CHECK_THAT(error, Catch::Contains("filmic") && Catch::Contains("linear") &&
                        Catch::Contains("reinhard") && Catch::Contains("aces"));
}

TEST_CASE("tonemap a whole image to RGB bytes", "[image][tonemap]") {
  pfx::app::Image img;
  img.width = 2;
  img.height = 1;
  img.rgba = {1.0f, 0.5f, 0.0f, 0.3f, std::nanf(""), 0.0f, 0.0f, 1.0f};
  const pfx::app::DisplayImage out = pfx::app::tonemap_to_srgb8(img, {});
  REQUIRE(out.width == 2);
  REQUIRE(out.channels == 3);
  CHECK(out.pixels == std::vector<std::uint8_t>{255, 188, 0, 255, 0, 255});
}
