// Non-finite input samples (nonfinite = zero | clamp): a NaN or infinite colour, albedo or emissive
// channel is read as 0 (zero), or NaN as 0 and +-Inf as +-65504 (clamp), before it is used, where
// there is geometry and where the colour only passes through; a non-finite normal lights nothing.
// Checked against values written here and against the CPU reference, which reads the same inputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <glad/gl.h>

#include "lights_rig.hpp"

using namespace lights_test;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Writes one RGBA texel of a G-buffer texture and the test's copy of it (as the texture stores it).
void poke(uint32_t texture, std::vector<float>* copy, int width, int x, int y, const float rgba[4]) {
  glTextureSubImage2D(texture, 0, x, y, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  float stored[4];
  glGetTextureSubImage(texture, 0, x, y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof stored, stored);
  for (int c = 0; c < 4; ++c) (*copy)[(size_t(y) * width + x) * 4 + c] = stored[c];
}

bool all_finite(const std::vector<float>& image) {
  for (float v : image)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

TEST_CASE("non-finite colour, albedo and emissive samples are read as 0 (zero) or as 0 and +-65504 (clamp)",
          "[tiledlights][gl][hard]") {
  pfx::app::Scene scene = floor_and_box();
  scene.lights = {point_light(0, 1.5f, 1.5f, 1, 0.8f, 0.6f, 3), point_light(-1.5f, 1, 0, 0.3f, 0.5f, 1, 2)};
  Captured captured = capture(scene, 24, 16);
  const int w = captured.width;
  // A pixel without geometry (the sky above the floor) and three on the floor.
  int sky = -1;
  for (int p = int(captured.depth.size()) - 1; p >= 0 && sky < 0; --p)
    if (std::isinf(captured.depth[p])) sky = p;
  REQUIRE(sky >= 0);
  const int sx = sky % w, sy = sky / w;
  REQUIRE(std::isfinite(captured.depth[2 * w + 3]));
  REQUIRE(std::isfinite(captured.depth[2 * w + 12]));
  REQUIRE(std::isfinite(captured.depth[3 * w + 20]));
  const float bad_color[4] = {kInf, kNaN, -kInf, 1}, bad_albedo[4] = {kNaN, kInf, 0.5f, 1},
              bad_normal[4] = {kNaN, 1, 0, 0}, bad_emissive[4] = {kInf, 2, -kInf, 1};
  poke(captured.textures.color, &captured.color, w, sx, sy, bad_color);
  poke(captured.textures.color, &captured.color, w, 3, 2, bad_color);
  poke(captured.textures.albedo, &captured.albedo, w, 12, 2, bad_albedo);
  poke(captured.textures.normal, &captured.normal, w, 20, 3, bad_normal);
  poke(captured.textures.emissive, &captured.emissive, w, 3, 2, bad_emissive);
  REQUIRE(std::isinf(captured.color[size_t(sky) * 4]));  // the texture really holds them
  REQUIRE(std::isnan(captured.albedo[(2 * w + 12) * 4]));

  for (const char* base : {"color", "emissive"}) {
    INFO("base " << base);
    Rig rig;
    rig.set(std::string("base=") + base);
    // zero, the default: brute force against the reference, every mode against brute force.
    const auto zero = check_modes(rig, captured);
    CHECK(all_finite(zero));
    // The sky passes through with its non-finite channels as 0.
    CHECK(zero[size_t(sky) * 4 + 0] == 0.0f);
    CHECK(zero[size_t(sky) * 4 + 1] == 0.0f);
    CHECK(zero[size_t(sky) * 4 + 2] == 0.0f);
    // The non-finite normal: no light, the base alone.
    const size_t n = size_t(3 * w + 20) * 4;
    const std::vector<float>& base_image = std::string(base) == "color" ? captured.color : captured.emissive;
    for (int c = 0; c < 3; ++c) CHECK(zero[n + c] == base_image[n + c]);
    // The NaN and Inf albedo channels: no light in them, the base alone; the finite one is lit.
    const size_t a = size_t(2 * w + 12) * 4;
    CHECK(zero[a + 0] == base_image[a + 0]);
    CHECK(zero[a + 1] == base_image[a + 1]);
    CHECK(zero[a + 2] > base_image[a + 2]);

    rig.set("nonfinite=clamp");
    const auto clamp = check_modes(rig, captured);
    CHECK(all_finite(clamp));
    CHECK(clamp[size_t(sky) * 4 + 0] == 65504.0f);
    CHECK(clamp[size_t(sky) * 4 + 1] == 0.0f);
    CHECK(clamp[size_t(sky) * 4 + 2] == -65504.0f);
    // +Inf albedo becomes 65504: that channel is lit very brightly (still finite).
    CHECK(clamp[a + 1] > 100.0f);
    const size_t p = size_t(2 * w + 3) * 4;
    if (std::string(base) == "color") {
      CHECK(zero[p + 0] < 100.0f);           // +Inf colour: 0 plus the light
      CHECK(clamp[p + 0] == 65504.0f);       // 65504 plus the light, stored as half
      CHECK(clamp[p + 2] < -60000.0f);
    } else {
      CHECK(zero[p + 2] < 100.0f);           // -Inf emissive: 0 plus the light
      CHECK(clamp[p + 0] == 65504.0f);
    }
  }
}
