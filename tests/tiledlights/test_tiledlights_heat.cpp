// show=list_heat: the heat colour of the lights each pixel sums. Checked against a heat ramp
// written here from the parameter's documented scale (log2(1 + n) / 10 through black, blue, green,
// yellow, red), with counts known from the scene: brute force sums every light; a culled mode's
// pixel that a light reaches counts it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "demo_scene.hpp"
#include "lights_rig.hpp"

using namespace lights_test;

namespace {

std::array<double, 3> expected_heat(double count) {
  const std::array<std::array<double, 3>, 5> stops = {
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}};
  const double t = std::clamp(std::log2(1 + count) / 10, 0.0, 1.0) * 4;
  const int i = std::min(static_cast<int>(t), 3);
  const double f = t - i;
  return {stops[i][0] + (stops[i + 1][0] - stops[i][0]) * f, stops[i][1] + (stops[i + 1][1] - stops[i][1]) * f,
          stops[i][2] + (stops[i + 1][2] - stops[i][2]) * f};
}

// The output is half float: 2^-10 relative, plus the float log2 of the shader.
bool shows(const std::vector<float>& out, size_t pixel, double count) {
  const auto heat = expected_heat(count);
  for (int c = 0; c < 3; ++c)
    if (std::abs(out[pixel * 4 + c] - heat[c]) > 2e-3) return false;
  return true;
}

bool has_geometry(float depth) { return depth > 0 && std::isfinite(depth); }

}  // namespace

TEST_CASE("heat ramp stops: 0 black, 4 blue, 31 green, 1023 red", "[tiledlights]") {
  CHECK(expected_heat(0) == std::array<double, 3>{0, 0, 0});
  CHECK(expected_heat(1023) == std::array<double, 3>{1, 0, 0});
  CHECK(expected_heat(1e6) == std::array<double, 3>{1, 0, 0});
  CHECK(expected_heat(31)[1] == Approx(1));
  CHECK(expected_heat(std::exp2(2.5) - 1)[2] == Approx(1));
}

TEST_CASE("list heat of brute force: every pixel with geometry shows every light, the rest passes",
          "[tiledlights][gl]") {
  Rig rig;
  rig.set("mode=brute");
  rig.set("show=list_heat");
  // The demo grid's lights peak at 0.25..4 x a corner colour: all are above the 0.05 cutoff. At 6
  // lights one light more or less changes the colour by about 0.09; at 400 by about 1e-5.
  for (size_t lights : {6, 400}) {
    INFO(lights << " lights");
    pfx::app::Scene scene = pfx::app::make_demo_scene({0, 3});
    scene.lights.resize(lights);
    const Captured captured = capture(scene, 48, 27);
    const Rendered r = rig.render(captured);
    REQUIRE(r.error.empty());
    size_t lit = 0;
    for (size_t p = 0; p < captured.depth.size(); ++p) {
      INFO("pixel " << p);
      if (has_geometry(captured.depth[p])) {
        REQUIRE(shows(r.output, p, static_cast<double>(lights)));
        if (lights < 10) REQUIRE_FALSE(shows(r.output, p, static_cast<double>(lights - 1)));
        ++lit;
      } else {
        for (int c = 0; c < 4; ++c) REQUIRE(r.output[p * 4 + c] == captured.color[p * 4 + c]);
      }
    }
    CHECK(lit > captured.depth.size() / 2);
  }
}

TEST_CASE("list heat of culled modes: one light counted where it reaches, black far from it", "[tiledlights][gl]") {
  Rig rig;
  // A 1.5 m light over the floor's front left: most of the view is out of its reach.
  pfx::app::Scene scene = floor_and_box();
  scene.lights = {point_light(-2, 0.5f, 3, 1, 1, 1, 2, 1.5f)};
  const Captured captured = capture(scene, 64, 48);
  rig.set("mode=brute");
  const Rendered brute = rig.render(captured);
  REQUIRE(brute.error.empty());
  rig.set("show=list_heat");
  // Small tiles, so that most of them lie out of the light's reach.
  rig.set("cpu_tiles_x=16");
  rig.set("cpu_tiles_y=12");
  rig.set("tile_size=4");
  rig.set("cluster_tile_size=8");
  for (const char* mode : {"cpu8x4", "tiled", "clustered"}) {
    INFO("mode " << mode);
    rig.set(std::string("mode=") + mode);
    const Rendered heat = rig.render(captured);
    REQUIRE(heat.error.empty());
    size_t reached = 0, zero = 0;
    for (size_t p = 0; p < captured.depth.size(); ++p) {
      if (!has_geometry(captured.depth[p])) continue;
      INFO("pixel " << p);
      bool lit = false;
      for (int c = 0; c < 3; ++c) lit = lit || brute.output[p * 4 + c] != captured.color[p * 4 + c];
      if (lit) {
        REQUIRE(shows(heat.output, p, 1));  // conservative: a reached pixel's list has the light
        ++reached;
      } else {
        REQUIRE((shows(heat.output, p, 0) || shows(heat.output, p, 1)));
        zero += shows(heat.output, p, 0);
      }
    }
    CHECK(reached > 0);
    CHECK(zero > captured.depth.size() / 4);  // the lists are not all "every light"
  }
}
