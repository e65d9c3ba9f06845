// The scene model our programs render (docs/architecture.md): meshes with materials, point lights
// and a camera. Nothing more than the effects need; no GL here (host/lib/scene's renderer uploads it).
// Units are metres, colours linear scene-referred, right-handed with +Y up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <pfx/effect.h>

namespace pfx::app {

// An RGBA texture, rows bottom first (as GL stores it), repeated over the UVs. Colour maps hold
// linear values (decoded from sRGB when they were read); data maps (alpha, normals) hold the
// file's codes / 255 as they are.
struct Texture {
  int width = 0, height = 0;
  std::vector<float> rgba;  // width * height * 4
};

// Texture indices are into Scene::textures, -1 for none.
struct Material {
  glm::vec3 albedo{0.8f};     // multiplied by albedo_texture's RGB when there is one
  int albedo_texture = -1;
  glm::vec3 emissive{0.0f};   // radiance the surface emits itself, times emissive_texture's RGB
  int emissive_texture = -1;
  // A cut-out: where alpha_texture's A is below alpha_cutoff the surface is not there at all.
  int alpha_texture = -1;
  float alpha_cutoff = 0.5f;
  // A tangent-space normal map (RGB = XYZ * 0.5 + 0.5, +Z out of the surface, +Y along +V).
  int normal_texture = -1;
};

// A distant light (the sun of an outdoor scene, the key light of a studio): every surface facing
// it receives radiance x max(0, n . direction).
struct DirectionalLight {
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, from the surface towards the light
  glm::vec3 radiance{0.0f};               // 0: no such light
};

// Indexed triangles in world space (our scenes are static: no per-mesh transform is needed).
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // unit, one per position
  std::vector<glm::vec2> uvs;         // one per position
  std::vector<uint32_t> indices;      // three per triangle, counter-clockwise seen from outside
  int material = 0;                   // index into Scene::materials
};

struct Camera {
  glm::dvec3 position{0.0, 0.0, 5.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovy_radians = 0.785398163397448;  // 45 degrees, vertical
  double near_plane = 0.1;                  // metres, > 0
  double far_plane = 1000.0;                // metres, > near; may be +infinity
};

struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  // Point lights as the ABI passes them (pfx_light: position, range <= 0 for "derive it", colour,
  // intensity), so a frame can point at this array directly.
  std::vector<pfx_light> lights;
  Camera camera;
  // Light that reaches every surface regardless of the point lights, a sky over a ground: a
  // surface whose normal points up receives `ambient`, one pointing down `ground_ambient`, and
  // in between a blend by the normal's height (0.5 + 0.5 n.y). With the key light, the host's
  // colour input is emissive + albedo x (that ambient + key light).
  glm::vec3 ambient{0.02f};
  glm::vec3 ground_ambient{0.02f};
  DirectionalLight key_light;
  // The colour where no geometry is.
  glm::vec3 background{0.01f, 0.012f, 0.02f};
  // An axis-aligned box holding every mesh (lights added with --lights are placed inside it).
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
};

// Checks the indices, sizes and numbers of a scene: false with *error naming the mesh, material,
// texture or light and what is wrong (NaN positions, indices out of range, a bad camera...).
bool validate_scene(const Scene& scene, std::string* error);

// Recomputes Scene::bounds_min/max from the meshes (both 0 for a scene without meshes).
void update_bounds(Scene* scene);

}  // namespace pfx::app
