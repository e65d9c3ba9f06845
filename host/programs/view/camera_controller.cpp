#include "camera_controller.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace pfx::app {
namespace {

constexpr double kPoleMargin = M_PI / 180.0;  // 1 degree
constexpr double kMinDistance = 1e-3;

glm::dvec3 unit_up(const Camera& camera) { return glm::normalize(camera.up); }

}  // namespace

void orbit_camera(Camera* camera, double yaw_radians, double pitch_radians) {
  const glm::dvec3 up = unit_up(*camera);
  glm::dvec3 offset = camera->position - camera->target;
  const double distance = glm::length(offset);
  offset = glm::angleAxis(yaw_radians, up) * offset;
  // The angle between offset and up is in (0, pi); keep it inside [margin, pi - margin].
  const double polar = std::acos(std::clamp(glm::dot(offset / distance, up), -1.0, 1.0));
  const double wanted = std::clamp(polar - pitch_radians, kPoleMargin, M_PI - kPoleMargin);
  const glm::dvec3 right = glm::cross(up, offset);
  // Turning about up x offset by a positive angle moves offset away from up (the polar angle grows).
  if (glm::length(right) > 0) offset = glm::angleAxis(wanted - polar, glm::normalize(right)) * offset;
  camera->position = camera->target + glm::normalize(offset) * distance;
}

void pan_camera(Camera* camera, double dx_pixels, double dy_pixels, int viewport_height) {
  const glm::dvec3 forward = camera->target - camera->position;
  const double distance = glm::length(forward);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera->up));
  const glm::dvec3 screen_up = glm::cross(right, forward / distance);
  // One pixel spans this many metres at the target's distance.
  const double metres_per_pixel = 2.0 * distance * std::tan(camera->fovy_radians / 2) / std::max(viewport_height, 1);
  const glm::dvec3 move = (-dx_pixels * right + dy_pixels * screen_up) * metres_per_pixel;
  camera->position += move;
  camera->target += move;
}

void zoom_camera(Camera* camera, double steps) {
  const glm::dvec3 offset = camera->position - camera->target;
  const double distance = glm::length(offset);
  const double wanted = std::max(distance * std::pow(0.85, steps), kMinDistance);
  camera->position = camera->target + offset * (wanted / distance);
}

void fly_camera(Camera* camera, const glm::dvec3& right_up_forward_metres) {
  const glm::dvec3 forward = glm::normalize(camera->target - camera->position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera->up));
  const glm::dvec3 move = right_up_forward_metres.x * right + right_up_forward_metres.y * unit_up(*camera) +
                          right_up_forward_metres.z * forward;
  camera->position += move;
  camera->target += move;
}

void frame_box(Camera* camera, const glm::dvec3& lo, const glm::dvec3& hi, double aspect) {
  const glm::dvec3 centre = (lo + hi) * 0.5;
  double radius = glm::length(hi - lo) * 0.5;
  if (!(radius > 0)) radius = 1.0;
  const double half_vertical = camera->fovy_radians / 2;
  const double half_horizontal = std::atan(std::tan(half_vertical) * aspect);
  const double distance = radius / std::sin(std::min(half_vertical, half_horizontal));
  glm::dvec3 direction = camera->position - camera->target;
  direction = glm::length(direction) > 0 ? glm::normalize(direction) : glm::dvec3(0, 0, 1);
  camera->target = centre;
  camera->position = centre + direction * distance;
  if (std::isfinite(camera->far_plane) && camera->far_plane < distance + radius)
    camera->far_plane = 2.0 * (distance + radius);
}

}  // namespace pfx::app
