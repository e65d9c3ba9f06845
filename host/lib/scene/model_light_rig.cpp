#include "model_light_rig.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "scene_random.hpp"

namespace pfx::app {
namespace {

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

glm::dvec3 mean_rgb(const Texture& texture) {
  glm::dvec3 sum(0.0);
  const size_t count = static_cast<size_t>(texture.width) * texture.height;
  for (size_t i = 0; i < count; ++i)
    sum += glm::dvec3(texture.rgba[i * 4], texture.rgba[i * 4 + 1], texture.rgba[i * 4 + 2]);
  return count ? sum / double(count) : glm::dvec3(1.0);
}

// The light the rig gives a surface of albedo 1, as a multiple of the exposure scale: key light
// (radiance 1) and sky and ground ambient.
constexpr double kKeyRadiance = 1.0;
const glm::dvec3 kSky(0.32, 0.36, 0.42);
const glm::dvec3 kGround(0.12, 0.11, 0.10);
// What a surface of the model's mean albedo, lit by the key at a typical angle and the ambient,
// should give: 0.2 linear is about 0.48 after sRGB encoding, the middle of the display range.
constexpr double kMidTone = 0.2;
constexpr double kTypicalLight = 0.55 * kKeyRadiance + 0.3;  // mean cosine of lit faces, mean ambient
// The point lights reach a fifth of the model's radius, and one at half that distance adds about
// as much as a quarter of the key light (times its own intensity of 0.25..4).
constexpr double kLightReach = 0.2;
constexpr double kLightShare = 0.25;
constexpr int kLightsAtFullShare = 400;

}  // namespace

double mean_albedo(const Scene& scene) {
  std::vector<glm::dvec3> texture_means(scene.textures.size(), glm::dvec3(-1.0));
  double area_sum = 0, weighted = 0;
  for (const Mesh& mesh : scene.meshes) {
    const Material& material = scene.materials[static_cast<size_t>(mesh.material)];
    glm::dvec3 albedo(material.albedo);
    if (material.albedo_texture >= 0) {
      glm::dvec3& m = texture_means[static_cast<size_t>(material.albedo_texture)];
      if (m.r < 0) m = mean_rgb(scene.textures[static_cast<size_t>(material.albedo_texture)]);
      albedo *= m;
    }
    double area = 0;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
          c(mesh.positions[mesh.indices[i + 2]]);
      area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    area_sum += area;
    weighted += area * luminance(albedo);
  }
  return area_sum > 0 && std::isfinite(weighted) ? weighted / area_sum : 0.8;
}

void add_model_light_rig(Scene* scene, const ModelLightRigOptions& options) {
  // Dark models are lit more, up to 16 times a white one's light, so they still read.
  const double albedo = std::clamp(mean_albedo(*scene), 0.05, 1.0);
  const double scale = kMidTone / (albedo * kTypicalLight);
  scene->key_light.direction = glm::normalize(glm::vec3(0.55f, 0.75f, 0.4f));
  scene->key_light.radiance = glm::vec3(static_cast<float>(kKeyRadiance * scale));
  scene->ambient = glm::vec3(kSky * scale);
  scene->ground_ambient = glm::vec3(kGround * scale);
  scene->background = glm::vec3(0.03f, 0.035f, 0.045f);

  const glm::vec3 lo = scene->bounds_min, hi = scene->bounds_max;
  const glm::vec3 center = (lo + hi) * 0.5f;
  const float radius = std::max(glm::length(hi - lo) * 0.5f, 1e-3f);
  // A flat model (a plane, a wall) still gets lights on both sides of its thin axis.
  const glm::vec3 half = glm::max((hi - lo) * 0.5f, glm::vec3(0.1f * radius));
  // Over and around: from a little below the middle to well above the top, and out past the
  // sides, leaving the model's own box (lights inside a closed model light nothing we see).
  const glm::vec3 field_lo(center.x - 1.3f * half.x, center.y - 0.3f * half.y, center.z - 1.3f * half.z);
  const glm::vec3 field_hi(center.x + 1.3f * half.x, center.y + 1.6f * half.y, center.z + 1.3f * half.z);
  const double reach = kLightReach * radius;
  const double count_share = options.point_lights > kLightsAtFullShare
                                 ? double(kLightsAtFullShare) / options.point_lights
                                 : 1.0;
  // The lights' falloff is 1 / (1 + d^2) in metres: at half the reach a light of intensity I adds
  // I / (1 + (reach/2)^2), so the intensity is multiplied by that denominator.
  const double intensity_scale =
      kLightShare * scale * count_share * (1.0 + 0.25 * reach * reach);
  SceneRandom random(options.seed ^ 0x7219a11c0ffee5ull);
  for (int i = 0; i < options.point_lights; ++i) {
    glm::vec3 p;
    for (int attempt = 0;; ++attempt) {
      p = glm::vec3(static_cast<float>(random.uniform(field_lo.x, field_hi.x)),
                    static_cast<float>(random.uniform(field_lo.y, field_hi.y)),
                    static_cast<float>(random.uniform(field_lo.z, field_hi.z)));
      const bool inside = p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
      if (!inside || attempt == 16) break;
    }
    pfx_light light = seed_light(p, random);
    light.intensity = static_cast<float>(light.intensity * intensity_scale);
    light.range = static_cast<float>(reach);
    scene->lights.push_back(light);
  }
}

}  // namespace pfx::app
