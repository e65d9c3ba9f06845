// The scene model's checks and the shapes made in code.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "shapes.hpp"

using namespace pfx::app;

namespace {

Scene one_box_scene() {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(make_box(glm::vec3(0), glm::vec3(1), 0));
  scene.camera.position = glm::dvec3(0, 0, 5);
  scene.camera.target = glm::dvec3(0);
  pfx_light light{};
  light.color[0] = 1;
  light.intensity = 1;
  scene.lights.push_back(light);
  return scene;
}

// Every triangle's winding agrees with its vertices' normals (counter-clockwise seen from outside).
void require_outward_winding(const Mesh& mesh) {
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    if (glm::length(face) < 1e-9f) continue;  // a pole's sliver
    const glm::vec3 n = mesh.normals[mesh.indices[t]] + mesh.normals[mesh.indices[t + 1]] + mesh.normals[mesh.indices[t + 2]];
    INFO("triangle " << t / 3);
    REQUIRE(glm::dot(face, n) > 0);
  }
}

}  // namespace

TEST_CASE("a valid scene passes its check", "[scene]") {
  std::string error;
  CHECK(validate_scene(one_box_scene(), &error));
  CHECK(error.empty());
}

TEST_CASE("a NaN light position is refused naming the light", "[scene][hard]") {
  Scene scene = one_box_scene();
  scene.lights.push_back(scene.lights[0]);
  scene.lights[1].position[1] = NAN;
  std::string error;
  CHECK_FALSE(validate_scene(scene, &error));
  CHECK(error.find("light 1") != std::string::npos);
}

TEST_CASE("an index past the vertices and a missing material are refused naming the mesh", "[scene][hard]") {
  Scene scene = one_box_scene();
  scene.meshes[0].indices.back() = 24;
  std::string error;
  CHECK_FALSE(validate_scene(scene, &error));
  CHECK(error.find("mesh 0: index 24") != std::string::npos);
  scene = one_box_scene();
  scene.meshes[0].material = 3;
  CHECK_FALSE(validate_scene(scene, &error));
  CHECK(error.find("mesh 0: material 3") != std::string::npos);
}

TEST_CASE("degenerate cameras are refused", "[scene][hard]") {
  std::string error;
  Scene scene = one_box_scene();
  scene.camera.target = scene.camera.position;
  CHECK_FALSE(validate_scene(scene, &error));
  CHECK(error.find("target is at the camera") != std::string::npos);
  scene = one_box_scene();
  scene.camera.up = glm::dvec3(0, 0, -3);  // along the view direction
  CHECK_FALSE(validate_scene(scene, &error));
  CHECK(error.find("parallel") != std::string::npos);
  scene = one_box_scene();
  scene.camera.far_plane = scene.camera.near_plane;
  CHECK_FALSE(validate_scene(scene, &error));
  scene = one_box_scene();
  scene.camera.near_plane = 0;
  CHECK_FALSE(validate_scene(scene, &error));
  scene = one_box_scene();
  scene.camera.fovy_radians = M_PI;
  CHECK_FALSE(validate_scene(scene, &error));
  scene = one_box_scene();
  scene.camera.far_plane = INFINITY;  // an infinite projection is fine
  CHECK(validate_scene(scene, &error));
}

TEST_CASE("box, sphere and floor wind counter-clockwise seen from outside, with unit normals", "[scene]") {
  const Mesh box = make_box(glm::vec3(1, 2, 3), glm::vec3(0.5f, 1, 2), 0);
  CHECK(box.positions.size() == 24);
  CHECK(box.indices.size() == 36);
  require_outward_winding(box);
  for (const glm::vec3& p : box.positions) {
    CHECK(std::abs(std::abs(p.x - 1) - 0.5f) < 1e-6f);
    CHECK(std::abs(std::abs(p.y - 2) - 1) < 1e-6f);
    CHECK(std::abs(std::abs(p.z - 3) - 2) < 1e-6f);
  }
  const Mesh sphere = make_sphere(glm::vec3(0, 1, 0), 2.0f, 12, 6, 0);
  require_outward_winding(sphere);
  for (size_t v = 0; v < sphere.positions.size(); ++v) {
    CHECK(glm::length(sphere.positions[v] - glm::vec3(0, 1, 0)) == Approx(2.0f).epsilon(1e-6));
    CHECK(glm::length(sphere.normals[v]) == Approx(1.0f).epsilon(1e-6));
  }
  const Mesh floor = make_floor(glm::vec3(0), 10, 2, 0);
  require_outward_winding(floor);
  CHECK(floor.normals[0] == glm::vec3(0, 1, 0));
}

TEST_CASE("bounds hold every vertex", "[scene]") {
  Scene scene = one_box_scene();
  scene.meshes.push_back(make_sphere(glm::vec3(5, 0, 0), 1, 8, 4, 0));
  update_bounds(&scene);
  CHECK(scene.bounds_min.x == Approx(-1));
  CHECK(scene.bounds_max.x == Approx(6));
  CHECK(scene.bounds_max.y == Approx(1));
}
