// The viewer's camera moves (host/programs/view/camera_controller.hpp), checked through the scene's own
// view and projection matrices (host/lib/scene/scene_camera.hpp): where points land on screen after
// each move, not how the move is computed.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "camera_controller.hpp"
#include "scene_camera.hpp"

using namespace pfx::app;

namespace {

// Normalised device coordinates of a world point seen by the camera.
glm::dvec3 ndc(const Camera& camera, double aspect, const glm::dvec3& point) {
  const glm::dvec4 clip = projection_matrix(camera, aspect) * view_matrix(camera) * glm::dvec4(point, 1.0);
  return glm::dvec3(clip) / clip.w;
}

Camera test_camera() {
  Camera camera;
  camera.position = {0, 0, 5};
  camera.target = {0, 0, 0};
  camera.up = {0, 1, 0};
  camera.fovy_radians = M_PI / 4;
  camera.near_plane = 0.1;
  camera.far_plane = 100;
  return camera;
}

void check_close(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-9) {
  INFO(a.x << " " << a.y << " " << a.z << " vs " << b.x << " " << b.y << " " << b.z);
  CHECK(glm::length(a - b) <= tolerance);
}

}  // namespace

TEST_CASE("orbit turns the camera about up around the target at the same distance", "[camera]") {
  Camera camera = test_camera();
  orbit_camera(&camera, M_PI / 2, 0);
  check_close(camera.position, {5, 0, 0});  // a quarter turn about +Y: +Z goes to +X
  check_close(camera.target, {0, 0, 0});
  CHECK(ndc(camera, 1.0, {0, 0, 0}).x == Approx(0).margin(1e-12));  // still looking at the target

  camera = test_camera();
  orbit_camera(&camera, 0, M_PI / 6);  // pitch up by 30 degrees: the camera rises
  CHECK(glm::length(camera.position) == Approx(5));
  CHECK(camera.position.y == Approx(5 * std::sin(M_PI / 6)));
  CHECK(camera.position.z == Approx(5 * std::cos(M_PI / 6)));
}

TEST_CASE("orbit stops short of the poles, so the view never flips", "[camera][hard]") {
  for (double pitch : {M_PI, -M_PI, 10.0, -10.0}) {
    Camera camera = test_camera();
    orbit_camera(&camera, 0.3, pitch);
    const glm::dvec3 offset = glm::normalize(camera.position - camera.target);
    const double angle_to_up = std::acos(glm::dot(offset, glm::dvec3(0, 1, 0)));
    CHECK(angle_to_up >= M_PI / 180 - 1e-9);
    CHECK(angle_to_up <= M_PI - M_PI / 180 + 1e-9);
    CHECK(glm::length(camera.position - camera.target) == Approx(5));
    // The view matrix stays finite (lookAt with a direction parallel to up would not be).
    const glm::dmat4 view = view_matrix(camera);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) CHECK(std::isfinite(view[c][r]));
  }
}

TEST_CASE("pan moves the point at the target's depth with the mouse", "[camera]") {
  Camera camera = test_camera();
  const double aspect = 16.0 / 9.0;
  const int height = 720;
  const glm::dvec3 old_target = camera.target;
  const glm::dvec3 offset = camera.position - camera.target;
  pan_camera(&camera, 100, -50, height);  // 100 px right, 50 px up
  check_close(camera.position - camera.target, offset);  // direction and distance kept
  // The old target was at the centre; it is now 100 px right and 50 px up of it (NDC y is up).
  const glm::dvec3 moved = ndc(camera, aspect, old_target);
  CHECK(moved.y * height / 2 == Approx(50));
  CHECK(moved.x * height * aspect / 2 == Approx(100));
}

TEST_CASE("zoom scales the distance to the target and keeps the direction", "[camera]") {
  Camera camera = test_camera();
  zoom_camera(&camera, 2);
  check_close(camera.position, {0, 0, 5 * 0.85 * 0.85});
  zoom_camera(&camera, -2);
  check_close(camera.position, {0, 0, 5});
  zoom_camera(&camera, 1000);  // never reaches or passes the target
  CHECK(camera.position.z == Approx(1e-3));
  CHECK(camera.position.z > 0);
}

TEST_CASE("fly moves camera and target together along the camera's axes", "[camera]") {
  Camera camera = test_camera();
  fly_camera(&camera, {1, 2, 3});  // 1 m right, 2 m up, 3 m forward (forward is -Z here)
  check_close(camera.position, {1, 2, 2});
  check_close(camera.target, {1, 2, -3});
}

TEST_CASE("framing a box puts all of it on screen, centred, whatever the aspect", "[camera]") {
  const glm::dvec3 lo(-20, 0, -10), hi(20, 4, 10);
  for (double aspect : {16.0 / 9.0, 1.0, 9.0 / 16.0, 4.0}) {
    Camera camera = test_camera();
    camera.position = {3, 7, -2};  // any start: the direction is kept
    const glm::dvec3 direction = glm::normalize(camera.position - camera.target);
    frame_box(&camera, lo, hi, aspect);
    check_close(camera.target, (lo + hi) * 0.5);
    check_close(glm::normalize(camera.position - camera.target), direction);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
      const glm::dvec3 n = ndc(camera, aspect, p);
      INFO("aspect " << aspect << " corner " << corner);
      CHECK(std::abs(n.x) <= 1.0);
      CHECK(std::abs(n.y) <= 1.0);
      CHECK(n.z > -1.0);  // in front of the near plane
      CHECK(n.z < 1.0);   // and before the far plane
    }
  }
}

TEST_CASE("framing moves a far plane that would cut the box, and frames an empty box as 1 m", "[camera][hard]") {
  Camera camera = test_camera();
  camera.far_plane = 1.0;
  frame_box(&camera, {-50, -50, -50}, {50, 50, 50}, 1.0);
  const double radius = std::sqrt(3.0) * 50;
  CHECK(camera.far_plane >= glm::length(camera.position - camera.target) + radius);

  camera = test_camera();
  camera.far_plane = INFINITY;
  frame_box(&camera, {2, 2, 2}, {2, 2, 2}, 1.0);
  check_close(camera.target, {2, 2, 2});
  CHECK(glm::length(camera.position - camera.target) == Approx(1.0 / std::sin(M_PI / 8)));
  CHECK(std::isinf(camera.far_plane));
}
