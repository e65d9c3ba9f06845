// A model file as a scene for pfx-render --scene: imported through the importer plugins
// (pfx/importer.h), one scene mesh per sub-mesh, materials from the file's Kd / Ke / map_Kd / map_Ke
// (PNG, JPEG, TGA or BMP: texture_maps.hpp), lit by the model light rig (model_light_rig.hpp), seen
// by a camera that frames the model's bounds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "scene.hpp"

namespace pfx::import {

struct SceneImportOptions {
  unsigned threads = 0;      // importer threads (0: all)
  uint64_t seed = 1;         // the point lights' colours and places
  int lights = 400;          // the point lights around the model (the demo's count)
  double fovy_degrees = 45;  // the camera's vertical field of view
};

// False with *error "FILE:LINE: reason" (the importer's message), or "FILE: ..." when no importer
// takes the file. Warnings (the importer's, and textures that could not be read) are appended.
bool load_scene_from_model(const pfx::host::PluginRegistry& registry, const std::string& path,
                           const SceneImportOptions& options, pfx::app::Scene* scene,
                           std::vector<std::string>* warnings, std::string* error);

// A camera looking at the box [lo, hi] from the front, above and to the right, far enough that the
// box's bounding sphere fills the vertical field of view.
pfx::app::Camera frame_bounds(const float lo[3], const float hi[3], double fovy_radians);

}  // namespace pfx::import
