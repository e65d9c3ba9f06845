// The G-buffer the host renders from a scene: the frame inputs of the ABI (docs/architecture.md) as GL
// textures of one size, written by one geometry pass.
//
//   color     RGBA16F  emissive + albedo x (sky/ground ambient + key light) where there is geometry
//                      (scene.hpp), the background elsewhere; the point lights are the effects' job
//   depth     R32F     linear view depth in metres (PFX_DEPTH_LINEAR); +infinity where nothing is
//   normal    RGBA16F  world-space unit normal in RGB (normal map applied), facing the camera; 0 where
//                      nothing is
//   albedo    RGBA16F  linear base colour (texture x colour) in RGB; 0 where nothing is
//   emissive  RGBA16F  emitted radiance in RGB; 0 where nothing is
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>

#include "scene.hpp"

namespace pfx::app {

class SceneRenderer {
 public:
  // Uploads the scene's meshes and textures and builds the geometry program; a GL 4.5 context
  // must be current (and stay current for every call). Null with *error when the scene is invalid
  // (validate_scene's message) or the GL refuses.
  static std::unique_ptr<SceneRenderer> create(const Scene& scene, std::string* error);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Renders the G-buffer seen by camera at width x height (>= 1; the textures are reallocated only
  // when the size changes). Leaves framebuffer 0, program 0 and vertex array 0 bound.
  void render(const Camera& camera, int width, int height);

  // The textures of the last render, for pfx::host::Chain::render.
  pfx::host::FrameTextures textures() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  SceneRenderer() = default;
  struct GpuMesh;
  void allocate(int width, int height);
  void release_targets();

  glm::vec3 ambient_{0.0f}, ground_{0.0f}, background_{0.0f};
  DirectionalLight key_light_;
  std::vector<Material> materials_;
  std::vector<uint32_t> textures_;  // one GL texture per scene Texture
  std::vector<std::unique_ptr<GpuMesh>> meshes_;
  uint32_t program_ = 0;
  uint32_t framebuffer_ = 0, depth_buffer_ = 0;
  uint32_t color_ = 0, depth_ = 0, normal_ = 0, albedo_ = 0, emissive_ = 0;
  int width_ = 0, height_ = 0;
};

// The pfx_frame for a G-buffer of this scene: size, the inputs it has (colour, depth, normal,
// albedo, emissive, lights), linear depth, the camera, and the scene's lights. The frame points at
// scene.lights: the scene must outlive it.
pfx_frame make_scene_frame(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace pfx::app
