// The G-buffer's material maps on a floor seen from above: an alpha map cuts the floor away where
// its alpha is below the cut-off, a normal map tilts the normal along the surface's U and V
// directions (worked out here from the floor's corners and UVs), and an emission map multiplies
// the emissive colour.
#include <catch2/catch.hpp>

#include <cmath>

#include <glad/gl.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "gbuffer.hpp"
#include "gl_test_support.hpp"
#include "shapes.hpp"

using namespace pfx::app;

namespace {

constexpr int kSize = 64;

// A 10 m floor filling the view of a camera 10 m above it, looking down with -Z up the picture,
// so picture x follows world +x (the floor's U) and picture y follows world -z (the floor's V).
Scene floor_from_above(const Material& material) {
  Scene scene;
  scene.materials = {material};
  scene.meshes.push_back(make_floor(glm::vec3(0), 10.0f, 1.0f, 0));
  scene.camera.position = glm::dvec3(0, 10, 0);
  scene.camera.target = glm::dvec3(0);
  scene.camera.up = glm::dvec3(0, 0, -1);
  scene.camera.fovy_radians = 2 * std::atan(0.4);  // the picture spans 8 m of the floor
  scene.camera.near_plane = 1;
  scene.camera.far_plane = 100;
  scene.ambient = scene.ground_ambient = glm::vec3(0.5f);
  update_bounds(&scene);
  return scene;
}

Texture solid(int width, int height, const glm::vec4& left, const glm::vec4& right) {
  Texture t;
  t.width = width;
  t.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec4& v = x < width / 2 ? left : right;
      t.rgba.insert(t.rgba.end(), {v.r, v.g, v.b, v.a});
    }
  return t;
}

struct Frame {
  std::vector<float> depth, normal, emissive;
};

Frame render(const Scene& scene) {
  pfx::test::gl_context();
  std::string error;
  auto renderer = SceneRenderer::create(scene, &error);
  INFO(error);
  REQUIRE(renderer);
  renderer->render(scene.camera, kSize, kSize);
  Frame f;
  f.depth.resize(kSize * kSize);
  f.normal.resize(kSize * kSize * 4);
  f.emissive.resize(kSize * kSize * 4);
  const auto t = renderer->textures();
  glGetTextureImage(t.depth, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(f.depth.size() * 4), f.depth.data());
  glGetTextureImage(t.normal, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(f.normal.size() * 4), f.normal.data());
  glGetTextureImage(t.emissive, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(f.emissive.size() * 4), f.emissive.data());
  REQUIRE(glGetError() == GL_NO_ERROR);
  return f;
}

}  // namespace

TEST_CASE("an alpha map cuts the surface away where its alpha is below the cut-off", "[scene][gl][maps]") {
  Material m;
  Scene scene = floor_from_above(m);
  // Alpha 0.2 on the left half of the texture (U < 0.5, world x < 0), 0.8 on the right.
  scene.textures.push_back(solid(64, 64, glm::vec4(1, 1, 1, 0.2f), glm::vec4(1, 1, 1, 0.8f)));
  scene.materials[0].alpha_texture = 0;
  const Frame f = render(scene);
  int cut = 0, kept = 0;
  for (int y = 4; y < kSize - 4; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (std::abs(x - kSize / 2) < 4) continue;  // the texture's seam, filtered
      const float d = f.depth[static_cast<size_t>(y) * kSize + x];
      if (x < kSize / 2) {
        CHECK(std::isinf(d));
        cut += std::isinf(d);
      } else {
        CHECK(d == Approx(10.0f).epsilon(1e-4));
        kept += std::isfinite(d);
      }
    }
  CHECK(cut > 1000);
  CHECK(kept > 1000);
  // The cut-off is the material's: at 0.1 nothing is cut.
  scene.materials[0].alpha_cutoff = 0.1f;
  const Frame all = render(scene);
  for (float d : all.depth) CHECK(d == Approx(10.0f).epsilon(1e-4));
}

TEST_CASE("a normal map tilts the normal along the surface's U and V", "[scene][gl][maps]") {
  Material m;
  Scene scene = floor_from_above(m);
  // Tangent-space (0.6, -0.48, 0.64) on the left, straight up (0, 0, 1) on the right.
  const glm::vec3 tilt(0.6f, -0.48f, 0.64f);
  scene.textures.push_back(solid(64, 64, glm::vec4(tilt * 0.5f + 0.5f, 1), glm::vec4(0.5f, 0.5f, 1, 1)));
  scene.materials[0].normal_texture = 0;
  const Frame f = render(scene);
  // On the floor U grows along +x and V along -z (its corners' UVs): T = +x, B = -z, N = +y.
  const glm::dvec3 expected_left = glm::normalize(glm::dvec3(tilt.x, tilt.z, -tilt.y));
  int checked = 0;
  for (int y = 4; y < kSize - 4; ++y)
    for (int x = 4; x < kSize - 4; ++x) {
      if (std::abs(x - kSize / 2) < 4) continue;
      const float* n = &f.normal[(static_cast<size_t>(y) * kSize + x) * 4];
      const glm::dvec3 want = x < kSize / 2 ? expected_left : glm::dvec3(0, 1, 0);
      INFO("pixel " << x << "," << y);
      CHECK(n[0] == Approx(want.x).margin(2e-3));
      CHECK(n[1] == Approx(want.y).margin(2e-3));
      CHECK(n[2] == Approx(want.z).margin(2e-3));
      ++checked;
    }
  CHECK(checked > 2000);
}

TEST_CASE("an emission map multiplies the emissive colour", "[scene][gl][maps]") {
  Material m;
  m.emissive = glm::vec3(4, 2, 1);
  Scene scene = floor_from_above(m);
  scene.textures.push_back(solid(64, 64, glm::vec4(0.25f, 0.5f, 1, 1), glm::vec4(0, 0, 0, 1)));
  scene.materials[0].emissive_texture = 0;
  const Frame f = render(scene);
  const float* left = &f.emissive[(static_cast<size_t>(kSize / 2) * kSize + 8) * 4];
  const float* right = &f.emissive[(static_cast<size_t>(kSize / 2) * kSize + kSize - 8) * 4];
  CHECK(left[0] == Approx(1.0f));
  CHECK(left[1] == Approx(1.0f));
  CHECK(left[2] == Approx(1.0f));
  CHECK(right[0] == 0.0f);
}
