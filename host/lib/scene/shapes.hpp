// Meshes made in code for the built-in scenes: a floor plane, boxes and UV spheres.
#pragma once

#include "scene.hpp"

namespace pfx::app {

// A horizontal square facing +Y, centred at center, side length size; UVs repeat uv_repeat times.
Mesh make_floor(const glm::vec3& center, float size, float uv_repeat, int material);
// An axis-aligned box with flat faces (24 vertices, 12 triangles).
Mesh make_box(const glm::vec3& center, const glm::vec3& half_extent, int material);
// A sphere of segments x rings quads (segments >= 3, rings >= 2), smooth normals.
Mesh make_sphere(const glm::vec3& center, float radius, int segments, int rings, int material);

}  // namespace pfx::app
