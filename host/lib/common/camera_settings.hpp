// Moving camera settings between the command line (--camera), presets and the scene camera, the
// same way in every program.
#pragma once

#include <string>
#include <vector>

#include "camera_options.hpp"
#include "preset.hpp"
#include "scene.hpp"

namespace pfx::app {

// The --camera keys given ("fovy", "near", "far") replace the camera's lens settings; its place
// and aim stay.
void apply_camera_keys(const CameraOptions& values, const std::vector<std::string>& keys, Camera* camera);

// The preset's camera with the --camera keys given replacing its lens values: the camera
// settings of a program that reads both, put together once and applied to whichever camera the
// frame has (a scene's, or an image's lens) with apply_preset_camera.
PresetCamera with_camera_keys(const PresetCamera& preset, const CameraOptions& values,
                              const std::vector<std::string>& keys);

// Every field the preset gives replaces the camera's.
void apply_preset_camera(const PresetCamera& preset, Camera* camera);
// The lens fields only: an image's camera has no place.
void apply_preset_camera(const PresetCamera& preset, CameraOptions* camera);

// Every field of the camera, for saving.
PresetCamera preset_camera_of(const Camera& camera);
PresetCamera preset_camera_of(const CameraOptions& camera);

}  // namespace pfx::app
