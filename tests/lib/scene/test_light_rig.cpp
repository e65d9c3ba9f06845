// The model light rig: the exposure follows the model's mean albedo (area-weighted, computed here
// by hand), and the rig is the same for a model at any scale and place, up to that scale.
#include <catch2/catch.hpp>

#include <cmath>

#include "model_light_rig.hpp"
#include "shapes.hpp"

using namespace pfx::app;

namespace {

// Boxes of albedo a (2 m cube) and b (a 4 m cube: four times the area), scaled and moved.
Scene two_boxes(double a, double b, float scale, const glm::vec3& offset) {
  Scene scene;
  Material ma, mb;
  ma.albedo = glm::vec3(static_cast<float>(a));
  mb.albedo = glm::vec3(static_cast<float>(b));
  scene.materials = {ma, mb};
  scene.meshes.push_back(make_box(offset + scale * glm::vec3(-3, 1, 0), scale * glm::vec3(1), 0));
  scene.meshes.push_back(make_box(offset + scale * glm::vec3(2, 2, 0), scale * glm::vec3(2), 1));
  update_bounds(&scene);
  return scene;
}

}  // namespace

TEST_CASE("the mean albedo is weighted by area and includes the albedo map", "[scene][rig]") {
  CHECK(mean_albedo(two_boxes(0.1, 0.6, 1, glm::vec3(0))) == Approx((1 * 0.1 + 4 * 0.6) / 5));
  Scene textured = two_boxes(1.0, 1.0, 1, glm::vec3(0));
  Texture half;
  half.width = 2;
  half.height = 1;
  half.rgba = {0.25f, 0.25f, 0.25f, 1, 0.75f, 0.75f, 0.75f, 1};
  textured.textures.push_back(half);
  textured.materials[1].albedo_texture = 0;
  CHECK(mean_albedo(textured) == Approx((1 * 1.0 + 4 * 0.5) / 5));
}

TEST_CASE("a darker model gets proportionally more light, down to an albedo of 0.05", "[scene][rig]") {
  Scene light = two_boxes(0.5, 0.5, 1, glm::vec3(0)), dark = two_boxes(0.1, 0.1, 1, glm::vec3(0)),
        black = two_boxes(0.0, 0.0, 1, glm::vec3(0));
  add_model_light_rig(&light, {});
  add_model_light_rig(&dark, {});
  add_model_light_rig(&black, {});
  CHECK(dark.key_light.radiance.r == Approx(5 * light.key_light.radiance.r));
  CHECK(dark.ambient.g == Approx(5 * light.ambient.g));
  CHECK(black.key_light.radiance.r == Approx(10 * light.key_light.radiance.r));
  CHECK(light.ambient.b > light.ground_ambient.b);  // a sky over a darker ground
}

TEST_CASE("the rig scales with the model: the same light at any size and place", "[scene][rig]") {
  Scene small = two_boxes(0.5, 0.5, 1, glm::vec3(0));
  Scene huge = two_boxes(0.5, 0.5, 250, glm::vec3(1000, -40, 7));
  add_model_light_rig(&small, {});
  add_model_light_rig(&huge, {});
  CHECK(small.key_light.radiance == huge.key_light.radiance);
  REQUIRE(small.lights.size() == 400);
  REQUIRE(huge.lights.size() == 400);
  for (size_t i = 0; i < small.lights.size(); ++i) {
    const pfx_light &s = small.lights[i], &h = huge.lights[i];
    for (int a = 0; a < 3; ++a) {
      const float expected = 250 * s.position[a] + glm::vec3(1000, -40, 7)[a];
      CHECK(h.position[a] == Approx(expected).margin(1e-3 * 250));
    }
    CHECK(h.range == Approx(250 * s.range).epsilon(1e-5));
    // The tiled shading falloff 1 / (1 + d^2) at half the range gives the same light at both sizes.
    const double at_small = s.intensity / (1 + 0.25 * s.range * s.range);
    const double at_huge = h.intensity / (1 + 0.25 * h.range * h.range);
    CHECK(at_huge == Approx(at_small).epsilon(1e-4));
    CHECK(h.color[0] == s.color[0]);
  }
}

TEST_CASE("more point lights (--lights N) share the same total light", "[scene][rig]") {
  Scene base = two_boxes(0.5, 0.5, 1, glm::vec3(0)), many = two_boxes(0.5, 0.5, 1, glm::vec3(0));
  add_model_light_rig(&base, {400, 1});
  add_model_light_rig(&many, {4000, 1});
  REQUIRE(many.lights.size() == 4000);
  double base_total = 0, many_total = 0;
  for (const auto& l : base.lights) base_total += l.intensity;
  for (const auto& l : many.lights) many_total += l.intensity;
  CHECK(many_total == Approx(base_total).epsilon(0.1));  // the same on average, 400 draws against 4000
}
