#include "light_field_scene.hpp"

#include <algorithm>
#include <cmath>

#include "demo_scene.hpp"
#include "shapes.hpp"

namespace pfx::app {

Scene make_light_field_scene(int light_count, uint64_t seed) {
  Scene scene = make_demo_scene({0, seed});
  const float side = static_cast<float>(std::max(44.0, std::sqrt(light_count / kLightFieldDensity)));
  // The demo's floor is its first mesh: replace it, keeping its material and texture scale.
  scene.meshes[0] = make_floor(glm::vec3(0), side, side / 4, scene.meshes[0].material);
  update_bounds(&scene);
  scene.lights.clear();
  add_random_lights(&scene, light_count, glm::vec3(-side / 2, 0.5f, -side / 2), glm::vec3(side / 2, 2.0f, side / 2),
                    seed);
  scene.camera.position = glm::dvec3(0, 16, 12);
  scene.camera.target = glm::dvec3(0, 0, 0);
  scene.camera.far_plane = 200;
  return scene;
}

}  // namespace pfx::app
