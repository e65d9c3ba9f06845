// Mouse and keyboard to camera moves (camera_controller.hpp), read from Dear ImGui's input state
// so a drag that starts on a panel never moves the camera.
#pragma once

#include "scene.hpp"

namespace pfx::app {

struct CameraInputSettings {
  double orbit_radians_per_pixel = 0.005;
  double fly_metres_per_second = 5.0;  // the viewer sets it from the scene's size
};

// Applies this frame's drags, wheel and held keys; dt_seconds is the time since the last frame.
// Returns true when the camera moved.
bool apply_camera_input(Camera* camera, const CameraInputSettings& settings, int viewport_height, double dt_seconds);

}  // namespace pfx::app
