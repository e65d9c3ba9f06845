#include "demo_scene.hpp"

#include <cmath>

#include "scene_random.hpp"
#include "shapes.hpp"

namespace pfx::app {
namespace {

// A checker board, so a moving or blurred floor is easy to see.
Texture checker_texture() {
  Texture texture;
  texture.width = texture.height = 64;
  texture.rgba.resize(64 * 64 * 4);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool light = ((x / 8) + (y / 8)) % 2 == 0;
      float* p = &texture.rgba[(static_cast<size_t>(y) * 64 + x) * 4];
      p[0] = light ? 0.75f : 0.35f;
      p[1] = light ? 0.72f : 0.34f;
      p[2] = light ? 0.68f : 0.33f;
      p[3] = 1.0f;
    }
  return texture;
}

int add_material(Scene* scene, const glm::vec3& albedo, const glm::vec3& emissive = glm::vec3(0), int texture = -1) {
  Material material;
  material.albedo = albedo;
  material.emissive = emissive;
  material.albedo_texture = texture;
  scene->materials.push_back(material);
  return static_cast<int>(scene->materials.size()) - 1;
}

}  // namespace

pfx_light seed_light(const glm::vec3& position, SceneRandom& random) {
  pfx_light light{};
  light.position[0] = position.x;
  light.position[1] = position.y;
  light.position[2] = position.z;
  light.range = 0;  // derived by the effect
  const double intensity = random.uniform(0.25, 4.0);
  const int c = random.integer(1, 7);
  light.color[0] = float(c & 1);
  light.color[1] = float((c >> 1) & 1);
  light.color[2] = float((c >> 2) & 1);
  light.intensity = static_cast<float>(intensity);
  return light;
}

void add_seed_light_grid(Scene* scene, uint64_t seed) {
  SceneRandom random(seed);
  for (int i = 0; i < 400; ++i) {
    const float x = static_cast<float>(i % 20) * 2 - 19;
    const float z = static_cast<float>(i / 20) * 2 - 19;
    scene->lights.push_back(seed_light(glm::vec3(x, 1.0f, z), random));
  }
}

void add_random_lights(Scene* scene, int count, const glm::vec3& lo, const glm::vec3& hi, uint64_t seed) {
  // A different stream from the grid's, so adding lights never recolours the grid.
  SceneRandom random(seed ^ 0x5eed11675eed1167ull);
  for (int i = 0; i < count; ++i) {
    const glm::vec3 position(static_cast<float>(random.uniform(lo.x, hi.x)),
                             static_cast<float>(random.uniform(lo.y, hi.y)),
                             static_cast<float>(random.uniform(lo.z, hi.z)));
    scene->lights.push_back(seed_light(position, random));
  }
}

Scene make_demo_scene(const DemoSceneOptions& options) {
  Scene scene;
  scene.textures.push_back(checker_texture());
  const int floor = add_material(&scene, glm::vec3(1.0f), glm::vec3(0), 0);
  const int white = add_material(&scene, glm::vec3(0.8f));
  const int clay = add_material(&scene, glm::vec3(0.7f, 0.45f, 0.3f));
  const int teal = add_material(&scene, glm::vec3(0.2f, 0.6f, 0.6f));
  // Emissive objects: a warm lamp sphere, a blue bar, a small very bright red cube, 12 to 60 times
  // the bloom's default threshold of 1, so they glow at default settings.
  const int lamp = add_material(&scene, glm::vec3(0.9f), glm::vec3(40.0f, 28.0f, 12.0f));
  const int neon = add_material(&scene, glm::vec3(0.1f), glm::vec3(2.0f, 8.0f, 30.0f));
  const int ember = add_material(&scene, glm::vec3(0.1f), glm::vec3(60.0f, 4.0f, 2.0f));

  scene.meshes.push_back(make_floor(glm::vec3(0), 44.0f, 11.0f, floor));
  // Three depths for the camera below, whose view axis meets the scene 10 m ahead (the
  // depth-of-field effect's default focus distance; its 24 degree view makes a 48 mm lens on the
  // effect's default 36 mm sensor, so f/1.4 blurs visibly): objects there stay sharp, a foreground
  // about 3 m from the lens blurs large (near field), and the background 20-40 m away blurs too
  // (far field). Objects stand between the lights (the grid is at odd coordinates).
  // In focus: the warm lamp, a white sphere, a clay box.
  scene.meshes.push_back(make_sphere(glm::vec3(0, 0.3f, 11), 0.3f, 32, 16, lamp));
  scene.meshes.push_back(make_sphere(glm::vec3(-1.4f, 0.55f, 10.6f), 0.55f, 48, 24, white));
  scene.meshes.push_back(make_box(glm::vec3(1.5f, 0.4f, 11.3f), glm::vec3(0.45f, 0.4f, 0.4f), clay));
  // Foreground, about 3 m from the lens: the blue neon bar and a teal sphere, floating.
  scene.meshes.push_back(make_box(glm::vec3(-0.55f, 1.25f, 17.9f), glm::vec3(0.35f, 0.04f, 0.04f), neon));
  scene.meshes.push_back(make_sphere(glm::vec3(0.6f, 1.35f, 17.7f), 0.22f, 32, 16, teal));
  // Background: the red ember, a tall teal box, white boxes and spheres, clay spheres.
  scene.meshes.push_back(make_box(glm::vec3(-5, 0.4f, -6), glm::vec3(0.4f, 0.4f, 0.4f), ember));
  scene.meshes.push_back(make_box(glm::vec3(8, 3.0f, -12), glm::vec3(1.0f, 3.0f, 1.0f), teal));
  scene.meshes.push_back(make_box(glm::vec3(-9, 1.5f, -10), glm::vec3(1.5f, 1.5f, 1.5f), white));
  scene.meshes.push_back(make_sphere(glm::vec3(3, 2.0f, -4), 2.0f, 48, 24, white));
  scene.meshes.push_back(make_sphere(glm::vec3(-12, 0.8f, -16), 0.8f, 24, 12, clay));
  scene.meshes.push_back(make_box(glm::vec3(-13, 0.5f, 4), glm::vec3(2.5f, 0.5f, 2.5f), white));
  scene.meshes.push_back(make_sphere(glm::vec3(10, 1.5f, 2), 1.5f, 32, 16, clay));
  update_bounds(&scene);

  add_seed_light_grid(&scene, options.seed);
  // Extra lights fill the floor's box from just above it to 4 m up.
  add_random_lights(&scene, options.extra_lights, glm::vec3(scene.bounds_min.x, 0.2f, scene.bounds_min.z),
                    glm::vec3(scene.bounds_max.x, 4.0f, scene.bounds_max.z), options.seed);

  // Low over the floor's front edge, so the grid's lights recede from 2 m to 40 m away.
  scene.camera.position = glm::dvec3(0, 2.2, 21);
  scene.camera.target = glm::dvec3(0, 0.6, 11.1);
  scene.camera.up = glm::dvec3(0, 1, 0);
  scene.camera.fovy_radians = 24.0 * M_PI / 180.0;
  scene.camera.near_plane = 0.1;
  scene.camera.far_plane = 200.0;
  return scene;
}

}  // namespace pfx::app
