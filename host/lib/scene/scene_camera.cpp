#include "scene_camera.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace pfx::app {

glm::dmat4 view_matrix(const Camera& camera) { return glm::lookAt(camera.position, camera.target, camera.up); }

glm::dmat4 projection_matrix(const Camera& camera, double aspect) {
  if (std::isinf(camera.far_plane)) return glm::infinitePerspective(camera.fovy_radians, aspect, camera.near_plane);
  return glm::perspective(camera.fovy_radians, aspect, camera.near_plane, camera.far_plane);
}

pfx_camera to_pfx_camera(const Camera& camera, int width, int height) {
  pfx_camera out{};
  const double aspect = double(width) / double(height);
  const glm::dmat4 view = view_matrix(camera);
  const glm::dmat4 projection = projection_matrix(camera, aspect);
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) {
      out.view[column * 4 + row] = static_cast<float>(view[column][row]);
      out.projection[column * 4 + row] = static_cast<float>(projection[column][row]);
    }
  out.near_plane = static_cast<float>(camera.near_plane);
  out.far_plane = static_cast<float>(camera.far_plane);
  out.fovy = static_cast<float>(camera.fovy_radians);
  out.aspect = static_cast<float>(aspect);
  return out;
}

}  // namespace pfx::app
