// The scene's camera as matrices and as the ABI's pfx_camera: a standard OpenGL perspective
// (window depth 0 at near, 1 at far, or an infinite far plane), looking from position to target.
#pragma once

#include <glm/mat4x4.hpp>

#include <pfx/effect.h>

#include "scene.hpp"

namespace pfx::app {

// World -> view (the camera at the origin looking down -Z), in double precision.
glm::dmat4 view_matrix(const Camera& camera);
// View -> clip for a frame of width / height = aspect.
glm::dmat4 projection_matrix(const Camera& camera, double aspect);
pfx_camera to_pfx_camera(const Camera& camera, int width, int height);

}  // namespace pfx::app
