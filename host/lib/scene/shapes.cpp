#include "shapes.hpp"

#include <cmath>

namespace pfx::app {
namespace {

// Appends one quad (a, b, c, d counter-clockwise seen from where normal points).
void add_quad(Mesh* mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
              const glm::vec3& normal) {
  const uint32_t base = static_cast<uint32_t>(mesh->positions.size());
  const glm::vec3 corners[4] = {a, b, c, d};
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) {
    mesh->positions.push_back(corners[i]);
    mesh->normals.push_back(normal);
    mesh->uvs.push_back(uvs[i]);
  }
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh->indices.push_back(base + i);
}

}  // namespace

Mesh make_floor(const glm::vec3& center, float size, float uv_repeat, int material) {
  Mesh mesh;
  mesh.material = material;
  const float h = 0.5f * size;
  add_quad(&mesh, center + glm::vec3(-h, 0, h), center + glm::vec3(h, 0, h), center + glm::vec3(h, 0, -h),
           center + glm::vec3(-h, 0, -h), glm::vec3(0, 1, 0));
  for (glm::vec2& uv : mesh.uvs) uv *= uv_repeat;
  return mesh;
}

Mesh make_box(const glm::vec3& center, const glm::vec3& half_extent, int material) {
  Mesh mesh;
  mesh.material = material;
  // Each face: its normal and two in-plane axes (u, v) with u x v = normal, so corners run
  // counter-clockwise seen from outside.
  const glm::vec3 faces[6][3] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                 {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                 {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
  for (const auto& face : faces) {
    const glm::vec3 n = face[0] * half_extent, u = face[1] * half_extent, v = face[2] * half_extent;
    add_quad(&mesh, center + n - u - v, center + n + u - v, center + n + u + v, center + n - u + v, face[0]);
  }
  return mesh;
}

Mesh make_sphere(const glm::vec3& center, float radius, int segments, int rings, int material) {
  Mesh mesh;
  mesh.material = material;
  for (int r = 0; r <= rings; ++r) {
    const double theta = M_PI * r / rings;  // 0 at the north pole
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * M_PI * s / segments;
      const glm::vec3 n(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                        static_cast<float>(-std::sin(theta) * std::sin(phi)));
      mesh.positions.push_back(center + radius * n);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(float(s) / segments, 1.0f - float(r) / rings);
    }
  }
  const uint32_t row = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r)
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = r * row + s, b = a + row, c = b + 1, d = a + 1;
      for (uint32_t i : {a, b, c, a, c, d}) mesh.indices.push_back(i);
    }
  return mesh;
}

}  // namespace pfx::app
