// The built-in demo scene: the 400-light grid, the extra seeded lights, reproducibility;
// and pfx-bench's light-field scene (its lights' density).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <set>

#include "demo_scene.hpp"
#include "light_field_scene.hpp"

using namespace pfx::app;

namespace {

bool same_lights(const std::vector<pfx_light>& a, const std::vector<pfx_light>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(pfx_light)) == 0;
}

}  // namespace

TEST_CASE("the demo holds the 20x20 light grid: 2 m apart, 1 m up, corner colours, intensity 0.25..4", "[scene]") {
  const Scene scene = make_demo_scene();
  std::string error;
  REQUIRE(validate_scene(scene, &error));
  REQUIRE(scene.lights.size() == 400);
  std::set<std::pair<int, int>> cells;
  std::set<int> colours;
  for (int i = 0; i < 400; ++i) {
    const pfx_light& light = scene.lights[i];
    // The grid: x = (i % 20) * 2 - 19, z = (i / 20) * 2 - 19.
    CHECK(light.position[0] == float((i % 20) * 2 - 19));
    CHECK(light.position[1] == 1.0f);
    CHECK(light.position[2] == float((i / 20) * 2 - 19));
    cells.insert({int(light.position[0]), int(light.position[2])});
    int code = 0;
    for (int c = 0; c < 3; ++c) {
      REQUIRE((light.color[c] == 0.0f || light.color[c] == 1.0f));
      code |= int(light.color[c]) << c;
    }
    CHECK(code != 0);  // never black
    colours.insert(code);
    CHECK(light.intensity >= 0.25f);
    CHECK(light.intensity <= 4.0f);
    CHECK(light.range == 0.0f);  // derived by the effect
  }
  CHECK(cells.size() == 400);
  CHECK(colours.size() == 7);  // 400 draws hit every corner
}

TEST_CASE("the demo has emissive objects bright enough to bloom and a camera that sees the grid", "[scene]") {
  const Scene scene = make_demo_scene();
  int bright = 0;
  for (const Mesh& mesh : scene.meshes) {
    const glm::vec3 e = scene.materials[mesh.material].emissive;
    if (std::max(e.r, std::max(e.g, e.b)) >= 10.0f) ++bright;
  }
  CHECK(bright >= 3);
  CHECK(scene.bounds_min.x <= -20.0f);
  CHECK(scene.bounds_max.x >= 20.0f);
}

TEST_CASE("extra lights (--lights) are seeded, inside the bounds, and leave the grid alone", "[scene]") {
  const Scene base = make_demo_scene();
  const Scene more = make_demo_scene({1000, 1});
  REQUIRE(more.lights.size() == 1400);
  CHECK(std::memcmp(base.lights.data(), more.lights.data(), 400 * sizeof(pfx_light)) == 0);
  for (size_t i = 400; i < more.lights.size(); ++i) {
    const pfx_light& light = more.lights[i];
    CHECK(light.position[0] >= more.bounds_min.x);
    CHECK(light.position[0] <= more.bounds_max.x);
    CHECK(light.position[2] >= more.bounds_min.z);
    CHECK(light.position[2] <= more.bounds_max.z);
    CHECK(light.position[1] >= 0.2f);
    CHECK(light.position[1] <= 4.0f);
    CHECK(light.intensity >= 0.25f);
    CHECK(light.intensity <= 4.0f);
  }
}

TEST_CASE("the seed (--seed) makes the scene reproducible and different seeds differ", "[scene]") {
  CHECK(same_lights(make_demo_scene({50, 7}).lights, make_demo_scene({50, 7}).lights));
  CHECK_FALSE(same_lights(make_demo_scene({50, 7}).lights, make_demo_scene({50, 8}).lights));
  // SplitMix64 from state 1, computed separately (Python): the first draw gives intensity
  // 0.25 + 3.75 * 0.566561... = 2.3746059..., the second draw % 7 gives colour code 1 (red).
  const Scene scene = make_demo_scene({0, 1});
  CHECK(scene.lights[0].intensity == Approx(2.374605906896053).epsilon(1e-7));
  CHECK(scene.lights[0].color[0] == 1.0f);
  CHECK(scene.lights[0].color[1] == 0.0f);
  CHECK(scene.lights[0].color[2] == 0.0f);
}

TEST_CASE("the light-field scene keeps one light per 4 square metres as the count grows", "[scene]") {
  for (int count : {1000, 10000, 100000}) {
    INFO(count << " lights");
    const pfx::app::Scene scene = pfx::app::make_light_field_scene(count, 7);
    REQUIRE(scene.lights.size() == static_cast<size_t>(count));
    std::string error;
    CHECK(pfx::app::validate_scene(scene, &error));
    // Every light above the floor's square, whose area is count / density.
    const double side = scene.bounds_max.x - scene.bounds_min.x;
    CHECK(side == Approx(std::sqrt(count / pfx::app::kLightFieldDensity)).epsilon(1e-6));
    CHECK(scene.bounds_max.z - scene.bounds_min.z == Approx(side).epsilon(1e-6));
    for (const pfx_light& light : scene.lights) {
      REQUIRE(std::abs(light.position[0]) <= side / 2);
      REQUIRE(std::abs(light.position[2]) <= side / 2);
      REQUIRE(light.position[1] >= 0.5f);
      REQUIRE(light.position[1] <= 2.0f);
    }
  }
  // Fewer lights than fill the view: the floor stays 44 m wide.
  const pfx::app::Scene few = pfx::app::make_light_field_scene(100, 7);
  CHECK(few.bounds_max.x - few.bounds_min.x == Approx(44).epsilon(1e-6));
}
