#include "camera_input.hpp"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "camera_controller.hpp"

namespace pfx::app {

bool apply_camera_input(Camera* camera, const CameraInputSettings& settings, int viewport_height, double dt_seconds) {
  const ImGuiIO& io = ImGui::GetIO();
  bool moved = false;
  if (!io.WantCaptureMouse) {
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    const bool dragging = dx != 0 || dy != 0;
    const bool pan = io.MouseDown[1] || io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift);
    if (dragging && pan) {
      pan_camera(camera, dx, dy, viewport_height);
      moved = true;
    } else if (dragging && io.MouseDown[0]) {
      // As if grabbing the scene: dragging right turns it right, dragging down tips its near edge
      // down (the camera rises to look from higher up).
      orbit_camera(camera, -dx * settings.orbit_radians_per_pixel, dy * settings.orbit_radians_per_pixel);
      moved = true;
    }
    if (io.MouseWheel != 0) {
      zoom_camera(camera, io.MouseWheel);
      moved = true;
    }
  }
  if (!io.WantCaptureKeyboard && !io.KeyCtrl) {
    auto held = [](int key) { return ImGui::IsKeyDown(key) ? 1.0 : 0.0; };
    const glm::dvec3 direction(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                               held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (direction != glm::dvec3(0.0)) {
      // dt is capped so one slow frame (a shader compile) does not throw the camera across the scene.
      const double metres = settings.fly_metres_per_second * (io.KeyShift ? 4.0 : 1.0) * std::min(dt_seconds, 0.1);
      fly_camera(camera, direction * metres);
      moved = true;
    }
  }
  return moved;
}

}  // namespace pfx::app
