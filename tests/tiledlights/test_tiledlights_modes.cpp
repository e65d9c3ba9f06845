// Every mode against brute force and brute force against the CPU reference, at 1, 400, 10,000
// and 100,000 lights (small frames for the large counts: llvmpipe runs brute force too); zero
// lights are a hard case (test_tiledlights_hard_cases.cpp).
#include <catch2/catch.hpp>

#include "demo_scene.hpp"
#include "lights_rig.hpp"

using namespace lights_test;

namespace {

// The demo scene with exactly `lights` lights: the grid's first ones, then seeded extra lights.
pfx::app::Scene demo_with(int lights) {
  pfx::app::Scene scene = pfx::app::make_demo_scene({lights > 400 ? lights - 400 : 0, 5});
  scene.lights.resize(static_cast<size_t>(lights));
  return scene;
}

}  // namespace

TEST_CASE("every mode equals brute force and brute force the reference with 1 light", "[tiledlights][gl]") {
  Rig rig;
  check_modes(rig, capture(demo_with(1), 64, 36));
}

TEST_CASE("every mode equals brute force and brute force the reference with 400 lights", "[tiledlights][gl]") {
  Rig rig;
  check_modes(rig, capture(demo_with(400), 96, 54));
}

TEST_CASE("every mode equals brute force and brute force the reference with 10000 lights", "[tiledlights][gl]") {
  Rig rig;
  check_modes(rig, capture(demo_with(10000), 40, 24));
}

TEST_CASE("every mode equals brute force and brute force the reference with 100000 lights", "[tiledlights][gl]") {
  Rig rig;
  const Captured captured = capture(demo_with(100000), 16, 10);
  check_modes(rig, captured);
  // More than llvmpipe's 65535 loop turns' worth of lights reach these pixels: all are summed.
  rig.set("mode=brute");
  CHECK(rig.render(captured).report["lights_uploaded"].get<int>() > 65535);
}

TEST_CASE("the reference tolerance catches lights whose range is 1 percent off", "[tiledlights][gl]") {
  Rig rig;
  const Captured captured = capture(demo_with(400), 64, 36);
  rig.set("mode=brute");
  const Rendered brute = rig.render(captured);
  REQUIRE(brute.error.empty());
  CHECK(worst_error_ratio(brute.output, rig.reference(captured, PFX_REFERENCE_MODEL)) <= 1.0);
  // cutoff 2% lower: ranges about 1% longer.
  rig.set("cutoff=0.049");
  CHECK(worst_error_ratio(brute.output, rig.reference(captured, PFX_REFERENCE_MODEL)) > 1.0);
}
