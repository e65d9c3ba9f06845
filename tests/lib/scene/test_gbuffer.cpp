// The G-buffer pass against ray casting done here in double precision: for every pixel whose
// neighbourhood hits one surface, depth, normal, albedo, emissive and colour (sky and ground
// ambient, key light) must be what that surface gives; where nothing is hit, depth is +infinity
// and colour the background.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include <glad/gl.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "demo_scene.hpp"
#include "gbuffer.hpp"
#include "gl_test_support.hpp"
#include "image_texture.hpp"
#include "scene_camera.hpp"
#include "shapes.hpp"

using namespace pfx::app;

namespace {

struct Hit {
  double depth = INFINITY;  // along the view axis
  int surface = -1;         // 0 floor, 1..6 box faces
  glm::dvec3 normal{0.0};
};

// A floor (20 m square at y = 0) and a box centred at (0, 1, 0) with half extent 1.
constexpr double kFloorHalf = 10.0;

Scene floor_and_box() {
  Scene scene;
  Material floor;
  floor.albedo = glm::vec3(0.5f, 0.5f, 0.5f);
  Material box;
  box.albedo = glm::vec3(0.25f, 0.5f, 0.75f);
  box.emissive = glm::vec3(3.0f, 2.0f, 1.0f);
  scene.materials = {floor, box};
  scene.meshes.push_back(make_floor(glm::vec3(0), float(2 * kFloorHalf), 1, 0));
  scene.meshes.push_back(make_box(glm::vec3(0, 1, 0), glm::vec3(1), 1));
  scene.camera.position = glm::dvec3(1.5, 5, 9);
  scene.camera.target = glm::dvec3(0, 0.5, 0);
  scene.camera.fovy_radians = 60.0 * M_PI / 180.0;
  scene.camera.near_plane = 0.1;
  scene.camera.far_plane = 100;
  scene.ambient = glm::vec3(0.125f);
  scene.ground_ambient = glm::vec3(0.0625f, 0.03125f, 0.0f);
  scene.key_light.direction = glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f));
  scene.key_light.radiance = glm::vec3(0.5f, 0.25f, 1.0f);
  scene.background = glm::vec3(0.25f, 0.5f, 1.0f);
  update_bounds(&scene);
  return scene;
}

// The ray through window position (px, py) (bottom-left origin), cast against floor and box.
Hit cast(const Camera& camera, int width, int height, double px, double py) {
  const double aspect = double(width) / height, t = std::tan(camera.fovy_radians / 2);
  const glm::dvec3 view_dir((2 * px / width - 1) * t * aspect, (2 * py / height - 1) * t, -1.0);  // view z = -1
  const glm::dmat3 to_world = glm::transpose(glm::dmat3(view_matrix(camera)));
  const glm::dvec3 d = to_world * view_dir, o = camera.position;
  Hit best;
  // The floor: y = 0 inside its square.
  if (d.y < 0) {
    const double s = -o.y / d.y;
    const glm::dvec3 p = o + s * d;
    if (std::abs(p.x) <= kFloorHalf && std::abs(p.z) <= kFloorHalf && s < best.depth) best = {s, 0, {0, 1, 0}};
  }
  // The box by slabs.
  const glm::dvec3 lo(-1, 0, -1), hi(1, 2, 1);
  double enter = -INFINITY, leave = INFINITY;
  int face = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (o[a] < lo[a] || o[a] > hi[a]) enter = INFINITY;
      continue;
    }
    double t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
    int f = 1 + 2 * a;  // entering through the low face
    if (t0 > t1) {
      std::swap(t0, t1);
      f = 2 + 2 * a;
    }
    if (t0 > enter) {
      enter = t0;
      face = f;
    }
    leave = std::min(leave, t1);
  }
  if (enter <= leave && enter > 0 && enter < best.depth) {
    glm::dvec3 n(0.0);
    const int axis = (face - 1) / 2;
    n[axis] = (face % 2 == 1) ? -1.0 : 1.0;
    best = {enter, face, n};
  }
  return best;  // s is the depth because the view-space direction has z = -1
}

std::vector<float> read_texture(uint32_t texture, int width, int height, GLenum format, int channels) {
  std::vector<float> data(static_cast<size_t>(width) * height * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  return data;
}

}  // namespace

TEST_CASE("G-buffer of a floor and a box matches rays cast in double precision", "[scene][gl]") {
  pfx::test::gl_context();
  const Scene scene = floor_and_box();
  std::string error;
  auto renderer = SceneRenderer::create(scene, &error);
  INFO(error);
  REQUIRE(renderer);
  const int w = 80, h = 60;
  renderer->render(scene.camera, w, h);
  const auto textures = renderer->textures();
  const auto color = read_texture(textures.color, w, h, GL_RGBA, 4);
  const auto depth = read_texture(textures.depth, w, h, GL_RED, 1);
  const auto normal = read_texture(textures.normal, w, h, GL_RGBA, 4);
  const auto albedo = read_texture(textures.albedo, w, h, GL_RGBA, 4);
  const auto emissive = read_texture(textures.emissive, w, h, GL_RGBA, 4);
  REQUIRE(glGetError() == GL_NO_ERROR);

  int checked = 0, sky = 0, box = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Hit centre = cast(scene.camera, w, h, x + 0.5, y + 0.5);
      // Skip silhouettes: every corner of the pixel must see the same surface.
      bool stable = true;
      for (double dx : {0.0, 1.0})
        for (double dy : {0.0, 1.0}) stable = stable && cast(scene.camera, w, h, x + dx, y + dy).surface == centre.surface;
      if (!stable) continue;
      const size_t i = static_cast<size_t>(y) * w + x;
      INFO("pixel " << x << "," << y << " surface " << centre.surface);
      if (centre.surface < 0) {
        REQUIRE(std::isinf(depth[i]));
        REQUIRE(color[i * 4 + 0] == 0.25f);
        REQUIRE(color[i * 4 + 2] == 1.0f);
        REQUIRE(normal[i * 4 + 1] == 0.0f);
        ++sky;
        continue;
      }
      REQUIRE(depth[i] == Approx(centre.depth).epsilon(1e-5));
      const Material& m = scene.materials[centre.surface == 0 ? 0 : 1];
      for (int c = 0; c < 3; ++c) {
        REQUIRE(normal[i * 4 + c] == Approx(centre.normal[c]).margin(1e-3));
        REQUIRE(albedo[i * 4 + c] == m.albedo[c]);  // exact in half
        REQUIRE(emissive[i * 4 + c] == m.emissive[c]);
        // Sky over ground by the normal's height, plus the key light by Lambert's cosine.
        const double up = 0.5 + 0.5 * centre.normal.y;
        const double ambient = scene.ground_ambient[c] + (scene.ambient[c] - scene.ground_ambient[c]) * up;
        const double key = scene.key_light.radiance[c] *
                           std::max(0.0, glm::dot(centre.normal, glm::dvec3(scene.key_light.direction)));
        REQUIRE(color[i * 4 + c] == Approx(m.emissive[c] + (ambient + key) * m.albedo[c]).epsilon(1e-3));
      }
      if (centre.surface > 0) ++box;
      ++checked;
    }
  CHECK(checked > w * h / 2);
  CHECK(sky > 50);
  CHECK(box > 100);
}

TEST_CASE("the frame of a scene names every G-buffer input, linear depth, the camera and the lights", "[scene]") {
  Scene scene = make_demo_scene({10, 3});
  const pfx_frame frame = make_scene_frame(scene, scene.camera, 32, 16);
  CHECK(frame.inputs == (PFX_INPUT_COLOR | PFX_INPUT_DEPTH | PFX_INPUT_NORMAL | PFX_INPUT_ALBEDO |
                         PFX_INPUT_EMISSIVE | PFX_INPUT_LIGHTS));
  CHECK(frame.depth_encoding == PFX_DEPTH_LINEAR);
  CHECK(frame.light_count == 410);
  CHECK(frame.lights == scene.lights.data());
  CHECK(frame.light_struct_size == sizeof(pfx_light));
  CHECK(frame.camera.aspect == 2.0f);
}

TEST_CASE("the demo scene renders finite, with sky at the top, the floor below and bright emitters", "[scene][gl]") {
  pfx::test::gl_context();
  const Scene scene = make_demo_scene();
  std::string error;
  auto renderer = SceneRenderer::create(scene, &error);
  REQUIRE(renderer);
  const int w = 96, h = 54;
  renderer->render(scene.camera, w, h);
  const auto color = read_texture(renderer->textures().color, w, h, GL_RGBA, 4);
  const auto depth = read_texture(renderer->textures().depth, w, h, GL_RED, 1);
  float brightest = 0;
  for (size_t i = 0; i < color.size(); ++i) {
    REQUIRE(std::isfinite(color[i]));
    brightest = std::max(brightest, color[i]);
  }
  CHECK(brightest >= 30.0f);
  CHECK(std::isinf(depth[static_cast<size_t>(h - 1) * w + w / 2]));  // top middle: sky
  CHECK(std::isfinite(depth[w / 2]));                                  // bottom middle: floor
  // Resizing reallocates; rendering again at another size works.
  renderer->render(scene.camera, 7, 5);
  CHECK(renderer->width() == 7);
  CHECK(glGetError() == GL_NO_ERROR);
}
