#include "camera_settings.hpp"

#include <cmath>

namespace pfx::app {
namespace {

constexpr double kDegrees = 180.0 / M_PI;

glm::dvec3 to_vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<double, 3> to_array(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

PresetCamera with_camera_keys(const PresetCamera& preset, const CameraOptions& values,
                              const std::vector<std::string>& keys) {
  PresetCamera camera = preset;
  for (const auto& key : keys) {
    if (key == "fovy") camera.fovy_degrees = values.fovy_degrees;
    if (key == "near") camera.near_plane = values.near_plane;
    if (key == "far") camera.far_plane = values.far_plane;
  }
  return camera;
}

void apply_camera_keys(const CameraOptions& values, const std::vector<std::string>& keys, Camera* camera) {
  apply_preset_camera(with_camera_keys(PresetCamera{}, values, keys), camera);
}

void apply_preset_camera(const PresetCamera& preset, Camera* camera) {
  if (preset.position && preset.target && preset.up) {
    camera->position = to_vec(*preset.position);
    camera->target = to_vec(*preset.target);
    camera->up = to_vec(*preset.up);
  }
  if (preset.fovy_degrees) camera->fovy_radians = *preset.fovy_degrees / kDegrees;
  if (preset.near_plane) camera->near_plane = *preset.near_plane;
  if (preset.far_plane) camera->far_plane = *preset.far_plane;
}

void apply_preset_camera(const PresetCamera& preset, CameraOptions* camera) {
  if (preset.fovy_degrees) camera->fovy_degrees = *preset.fovy_degrees;
  if (preset.near_plane) camera->near_plane = *preset.near_plane;
  if (preset.far_plane) camera->far_plane = *preset.far_plane;
}

PresetCamera preset_camera_of(const Camera& camera) {
  PresetCamera out;
  out.position = to_array(camera.position);
  out.target = to_array(camera.target);
  out.up = to_array(camera.up);
  out.fovy_degrees = camera.fovy_radians * kDegrees;
  out.near_plane = camera.near_plane;
  out.far_plane = camera.far_plane;
  return out;
}

PresetCamera preset_camera_of(const CameraOptions& camera) {
  PresetCamera out;
  out.fovy_degrees = camera.fovy_degrees;
  out.near_plane = camera.near_plane;
  out.far_plane = camera.far_plane;
  return out;
}

}  // namespace pfx::app
