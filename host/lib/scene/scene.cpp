#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace pfx::app {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

bool validate_scene(const Scene& scene, std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& texture = scene.textures[t];
    if (texture.width < 1 || texture.height < 1 ||
        texture.rgba.size() != static_cast<size_t>(texture.width) * texture.height * 4)
      return fail("texture " + std::to_string(t) + ": size and pixel count disagree");
  }
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& material = scene.materials[m];
    if (!finite(material.albedo) || !finite(material.emissive))
      return fail("material " + std::to_string(m) + ": albedo and emissive must be finite");
    for (int texture : {material.albedo_texture, material.emissive_texture, material.alpha_texture,
                        material.normal_texture})
      if (texture >= static_cast<int>(scene.textures.size()))
        return fail("material " + std::to_string(m) + ": texture " + std::to_string(texture) + " does not exist");
    if (!std::isfinite(material.alpha_cutoff))
      return fail("material " + std::to_string(m) + ": the alpha cut-off must be finite");
  }
  if (!finite(scene.ambient) || !finite(scene.ground_ambient) || !finite(scene.key_light.radiance) ||
      !finite(scene.key_light.direction) || !finite(scene.background))
    return fail("ambient, ground, key light and background must be finite");
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    const std::string name = "mesh " + std::to_string(i);
    if (mesh.normals.size() != mesh.positions.size() || mesh.uvs.size() != mesh.positions.size())
      return fail(name + ": positions, normals and uvs must have the same count");
    if (mesh.indices.size() % 3 != 0) return fail(name + ": the index count is not a multiple of 3");
    if (mesh.material < 0 || mesh.material >= static_cast<int>(scene.materials.size()))
      return fail(name + ": material " + std::to_string(mesh.material) + " does not exist");
    for (uint32_t index : mesh.indices)
      if (index >= mesh.positions.size())
        return fail(name + ": index " + std::to_string(index) + " is past its " +
                    std::to_string(mesh.positions.size()) + " vertices");
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      if (!finite(mesh.positions[v]) || !finite(mesh.normals[v]))
        return fail(name + ": vertex " + std::to_string(v) + " is not finite");
  }
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const pfx_light& light = scene.lights[l];
    const glm::vec3 position(light.position[0], light.position[1], light.position[2]);
    const glm::vec3 color(light.color[0], light.color[1], light.color[2]);
    if (!finite(position) || !finite(color) || !std::isfinite(light.intensity) || std::isnan(light.range))
      return fail("light " + std::to_string(l) + ": position, colour and intensity must be finite");
  }
  const Camera& camera = scene.camera;
  if (!finite(camera.position) || !finite(camera.target) || !finite(camera.up))
    return fail("camera: position, target and up must be finite");
  const glm::dvec3 forward = camera.target - camera.position;
  if (glm::length(forward) <= 0) return fail("camera: the target is at the camera's position");
  if (glm::length(glm::cross(forward, camera.up)) <= 1e-12 * glm::length(forward) * glm::length(camera.up))
    return fail("camera: up is parallel to the viewing direction");
  if (!(camera.fovy_radians > 0 && camera.fovy_radians < M_PI)) return fail("camera: fovy must be in (0, 180) degrees");
  if (!(camera.near_plane > 0) || std::isinf(camera.near_plane)) return fail("camera: near must be a positive distance");
  if (!(camera.far_plane > camera.near_plane)) return fail("camera: far must be greater than near");
  return true;
}

void update_bounds(Scene* scene) {
  const float inf = std::numeric_limits<float>::infinity();
  glm::vec3 lo(inf), hi(-inf);
  for (const Mesh& mesh : scene->meshes)
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
  scene->bounds_min = lo;
  scene->bounds_max = hi;
}

}  // namespace pfx::app
