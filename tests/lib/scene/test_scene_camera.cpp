// The scene camera's matrices: the target lands in the middle of the frame, distances are view depths.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "scene_camera.hpp"

using namespace pfx::app;

TEST_CASE("the camera's target projects to the centre and its distance is its view depth", "[scene]") {
  Camera camera;
  camera.position = glm::dvec3(3, 4, 12);
  camera.target = glm::dvec3(-1, 0, 2);
  camera.fovy_radians = 0.9;
  const glm::dmat4 view = view_matrix(camera);
  const glm::dvec4 v = view * glm::dvec4(camera.target, 1.0);
  CHECK(v.x == Approx(0).margin(1e-12));
  CHECK(v.y == Approx(0).margin(1e-12));
  CHECK(-v.z == Approx(glm::length(camera.target - camera.position)));
  const glm::dvec4 clip = projection_matrix(camera, 16.0 / 9.0) * v;
  CHECK(clip.w == Approx(-v.z));
  CHECK(clip.x / clip.w == Approx(0).margin(1e-12));

  // A point on the top edge of the view: tan(fovy / 2) up at depth d is at NDC y = 1.
  const double d = 7.0;
  const glm::dvec4 top(0.0, d * std::tan(camera.fovy_radians / 2), -d, 1.0);
  const glm::dvec4 top_clip = projection_matrix(camera, 2.0) * top;
  CHECK(top_clip.y / top_clip.w == Approx(1.0));
}

TEST_CASE("pfx_camera carries the matrices column-major with near, far, fovy and aspect", "[scene]") {
  Camera camera;
  camera.far_plane = INFINITY;
  const pfx_camera c = to_pfx_camera(camera, 200, 100);
  CHECK(c.aspect == 2.0f);
  CHECK(std::isinf(c.far_plane));
  CHECK(c.projection[11] == -1.0f);  // column 2, row 3: w = -z
  CHECK(c.view[14] == Approx(-5.0f));  // the default camera sits 5 m up +Z looking at the origin
}
