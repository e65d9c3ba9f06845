#include "import_scene.hpp"

#include <cmath>
#include <filesystem>
#include <algorithm>
#include <map>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>
#include <pfx/host/import_result.hpp>

#include "model_light_rig.hpp"
#include "texture_maps.hpp"

namespace pfx::import {

namespace {

// A material's map as a scene texture, each file read once per kind; -1 (and one warning per
// file) when it cannot be read, so the material keeps its flat colour.
int load_texture(const std::string& path, pfx::app::MapKind kind, pfx::app::Scene* scene,
                 std::map<std::pair<std::string, pfx::app::MapKind>, int>* loaded, std::vector<std::string>* warnings) {
  if (auto it = loaded->find({path, kind}); it != loaded->end()) return it->second;
  pfx::app::Texture texture;
  std::string problem;
  int index = -1;
  if (pfx::app::load_map(path, kind, &texture, &problem)) {
    scene->textures.push_back(std::move(texture));
    index = static_cast<int>(scene->textures.size() - 1);
  } else {
    const bool warned = std::any_of(loaded->begin(), loaded->end(),
                                    [&](const auto& entry) { return entry.first.first == path && entry.second < 0; });
    if (!warned) warnings->push_back("texture not used, flat colour instead: " + problem);
  }
  (*loaded)[{path, kind}] = index;
  return index;
}

}  // namespace

pfx::app::Camera frame_bounds(const float lo[3], const float hi[3], double fovy_radians) {
  const glm::dvec3 low(lo[0], lo[1], lo[2]), high(hi[0], hi[1], hi[2]);
  const glm::dvec3 center = (low + high) * 0.5;
  const double radius = std::max(glm::length(high - low) * 0.5, 1e-3);
  const double distance = radius / std::sin(fovy_radians * 0.5) * 1.05;
  pfx::app::Camera camera;
  camera.target = center;
  camera.position = center + glm::normalize(glm::dvec3(0.45, 0.4, 1.0)) * distance;
  camera.up = glm::dvec3(0, 1, 0);
  camera.fovy_radians = fovy_radians;
  camera.near_plane = std::max(distance - radius * 1.5, distance * 0.01);
  camera.far_plane = distance + radius * 3.0;
  return camera;
}

bool load_scene_from_model(const pfx::host::PluginRegistry& registry, const std::string& path,
                           const SceneImportOptions& options, pfx::app::Scene* scene,
                           std::vector<std::string>* warnings, std::string* error) {
  const pfx::host::ImporterInfo* importer = registry.find_importer_for_path(path);
  if (!importer) {
    *error = path + ": no importer plugin takes this file's extension";
    return false;
  }
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = path.c_str();
  request.threads = options.threads;
  const pfx::host::ImportResult result(*importer->desc, request);
  if (!result.ok()) {
    *error = result.error() ? result.error() : path + ": import failed";
    return false;
  }
  const pfx_import_result& r = *result;
  for (uint32_t i = 0; i < r.warning_count; ++i) warnings->push_back(r.warnings[i]);

  pfx::app::Scene out;
  // Scene material i + 1 is the file's material i; 0 is the default for faces without one.
  out.materials.push_back(pfx::app::Material{});
  std::map<std::pair<std::string, pfx::app::MapKind>, int> textures;
  const auto* bytes = reinterpret_cast<const unsigned char*>(r.materials);
  for (uint32_t m = 0; m < r.material_count; ++m) {
    const auto& material = *reinterpret_cast<const pfx_import_material*>(bytes + size_t{m} * r.materials[0].struct_size);
    pfx::app::Material scene_material;
    scene_material.albedo = glm::vec3(material.diffuse[0], material.diffuse[1], material.diffuse[2]);
    scene_material.emissive = glm::vec3(material.emissive[0], material.emissive[1], material.emissive[2]);
    if (material.diffuse_map && r.texcoords)
      scene_material.albedo_texture =
          load_texture(material.diffuse_map, pfx::app::MapKind::color, &out, &textures, warnings);
    if (material.emissive_map && r.texcoords) {
      scene_material.emissive_texture =
          load_texture(material.emissive_map, pfx::app::MapKind::color, &out, &textures, warnings);
      // A glow map under a black (or absent) Ke would show nothing: the map alone gives the colour.
      if (scene_material.emissive_texture >= 0 && scene_material.emissive == glm::vec3(0.0f))
        scene_material.emissive = glm::vec3(1.0f);
    }
    // Since ABI 1.3; an importer built against an older header has no such fields.
    if (PFX_STRUCT_HAS(&material, pfx_import_material, normal_map) && r.texcoords) {
      if (material.alpha_map)
        scene_material.alpha_texture = load_texture(material.alpha_map, pfx::app::MapKind::alpha, &out, &textures, warnings);
      // norm wins over bump when a material has both: it is the map made for shading.
      if (material.normal_map)
        scene_material.normal_texture =
            load_texture(material.normal_map, pfx::app::MapKind::normal, &out, &textures, warnings);
      else if (material.bump_map)
        scene_material.normal_texture = load_texture(material.bump_map, pfx::app::MapKind::bump, &out, &textures, warnings);
    }
    out.materials.push_back(scene_material);
  }
  // One mesh per sub-mesh, holding only the vertices it uses.
  for (uint32_t s = 0; s < r.submesh_count; ++s) {
    const pfx_import_submesh& sub = r.submeshes[s];
    pfx::app::Mesh mesh;
    mesh.material = sub.material == PFX_IMPORT_NONE ? 0 : static_cast<int>(sub.material) + 1;
    std::unordered_map<uint32_t, uint32_t> local;
    for (uint32_t k = 0; k < sub.index_count; ++k) {
      const uint32_t v = r.indices[sub.first_index + k];
      auto [it, fresh] = local.emplace(v, static_cast<uint32_t>(mesh.positions.size()));
      if (fresh) {
        mesh.positions.emplace_back(r.positions[3 * size_t{v}], r.positions[3 * size_t{v} + 1], r.positions[3 * size_t{v} + 2]);
        glm::vec3 n(r.normals[3 * size_t{v}], r.normals[3 * size_t{v} + 1], r.normals[3 * size_t{v} + 2]);
        const float length = glm::length(n);
        mesh.normals.push_back(length > 0 && std::isfinite(length) ? n / length : glm::vec3(0, 0, 1));
        mesh.uvs.emplace_back(r.texcoords ? glm::vec2(r.texcoords[2 * size_t{v}], r.texcoords[2 * size_t{v} + 1]) : glm::vec2(0));
      }
      mesh.indices.push_back(it->second);
    }
    out.meshes.push_back(std::move(mesh));
  }
  pfx::app::update_bounds(&out);
  pfx::app::add_model_light_rig(&out, {options.lights, options.seed});
  out.camera = frame_bounds(r.bounds_min, r.bounds_max, options.fovy_degrees * M_PI / 180.0);
  *scene = std::move(out);
  return true;
}

}  // namespace pfx::import
