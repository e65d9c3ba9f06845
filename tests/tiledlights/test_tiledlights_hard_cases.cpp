// The named hard cases: zero lights, lights behind the camera, through the near plane, around the
// camera, covering the whole view, zero intensity, bad light values, odd sizes and 1x1, other depth
// encodings, the sqrt-colour range rule (id seed), the emissive base. Crowded lists: test_tiledlights_dense.cpp.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "demo_scene.hpp"
#include "image_texture.hpp"
#include "lights_rig.hpp"

using namespace lights_test;

namespace {

bool log_mentions(const Rendered& r, const std::string& text) {
  for (const auto& line : r.log)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

// A scene lit by the given lights only.
pfx::app::Scene lit(std::vector<pfx_light> lights) {
  pfx::app::Scene scene = floor_and_box();
  scene.lights = std::move(lights);
  return scene;
}

}  // namespace

TEST_CASE("zero lights: the colour passes unchanged and no pass runs", "[tiledlights][gl][hard]") {
  Rig rig;
  const Captured captured = capture(lit({}), 40, 30);
  for (const char* mode : {"brute", "cpu8x4", "tiled", "clustered"}) {
    rig.set(std::string("mode=") + mode);
    const Rendered r = rig.render(captured);
    REQUIRE(r.error.empty());
    CHECK(r.passes == 0);
    require_identical(r.output, captured.color, captured.width);
  }
}

TEST_CASE("zero lights with the emissive base: emissive where there is geometry, colour elsewhere",
          "[tiledlights][gl][hard]") {
  Rig rig;
  rig.set("base=emissive");
  const Captured captured = capture(lit({}), 40, 30);
  const auto out = check_modes(rig, captured);
  for (size_t p = 0; p < captured.depth.size(); ++p)
    for (int c = 0; c < 3; ++c)
      REQUIRE(out[p * 4 + c] == (std::isinf(captured.depth[p]) ? captured.color[p * 4 + c] : captured.emissive[p * 4 + c]));
}

TEST_CASE("lights behind the camera, some reaching in front of it", "[tiledlights][gl][hard]") {
  Rig rig;
  // The camera is at (0, 3, 8) looking towards -Z: these lights are behind it.
  check_modes(rig, capture(lit({point_light(0, 2, 10, 1, 1, 1, 3, 6), point_light(-3, 1, 12, 1, 0, 0, 4, 9),
                                point_light(2, 4, 15, 0, 1, 0, 2, 3), point_light(0, 3, 30, 0, 0, 1, 4)}),
                           48, 32));
}

TEST_CASE("lights straddling the near plane", "[tiledlights][gl][hard]") {
  Rig rig;
  pfx::app::Scene scene = lit({});
  scene.camera.near_plane = 0.5;
  // Centres 0.2 .. 0.8 m in front of the eye along its view direction, ranges crossing near.
  const glm::dvec3 eye = scene.camera.position, forward = glm::normalize(scene.camera.target - eye);
  for (double t : {0.2, 0.45, 0.5, 0.55, 0.8}) {
    const glm::dvec3 p = eye + t * forward;
    scene.lights.push_back(point_light(float(p.x), float(p.y), float(p.z), 1, 0.5f, 0.25f, 2, 6));
  }
  check_modes(rig, capture(scene, 48, 32));
}

TEST_CASE("the camera inside a light's range, and a light whose range covers the whole view", "[tiledlights][gl][hard]") {
  Rig rig;
  check_modes(rig, capture(lit({point_light(0.1f, 3.0f, 8.2f, 1, 1, 1, 5, 12),     // around the eye
                                point_light(0, 60, 0, 0.2f, 0.3f, 1, 2000, 1000)}),  // over everything
                           48, 32));
}

TEST_CASE("zero-intensity and black lights reach nothing and change nothing", "[tiledlights][gl][hard]") {
  Rig rig;
  std::vector<pfx_light> lights = {point_light(1, 1, 1, 1, 1, 1, 2), point_light(-1, 1, 2, 0, 1, 0, 3)};
  const Captured few = capture(lit(lights), 40, 30);
  rig.set("mode=tiled");
  const Rendered reference = rig.render(few);
  for (int i = 0; i < 500; ++i) lights.push_back(point_light(float(i % 10) - 5, 1, float(i / 50), 1, 1, 1, 0));
  lights.push_back(point_light(0, 1, 0, 0, 0, 0, 5));
  lights.push_back(point_light(0, 1, 0, 0, 0, 0, 0, 10));  // an explicit range, but black
  const Captured many = capture(lit(lights), 40, 30);
  check_modes(rig, many);
  rig.set("mode=tiled");
  const Rendered r = rig.render(many);
  CHECK(r.report["lights"] == 504);
  CHECK(r.report["lights_reaching"] == 3);  // the black light with a range still "reaches"
  require_identical(r.output, reference.output, 40);
}

TEST_CASE("a NaN light position is refused with an error naming the light", "[tiledlights][gl][hard]") {
  Rig rig;
  pfx::app::Scene scene = lit({point_light(0, 1, 0, 1, 1, 1, 1), point_light(1, 1, 0, 1, 1, 1, 1),
                               point_light(2, 1, 0, 1, 1, 1, 1)});
  const Captured captured = capture(scene, 16, 16);
  // The scene renderer refuses such a scene, so break the light in the captured frame.
  Captured broken = capture(scene, 16, 16);
  broken.lights[2].position[1] = NAN;
  for (const char* mode : {"brute", "cpu8x4", "tiled", "clustered"}) {
    rig.set(std::string("mode=") + mode);
    const Rendered r = rig.render(broken);
    CHECK_FALSE(r.error.empty());
    CHECK(log_mentions(r, "light 2: position is not finite"));
  }
  // Infinite intensity, a negative colour and a NaN range are refused the same way.
  broken.lights[2].position[1] = 1;
  broken.lights[1].intensity = INFINITY;
  CHECK(log_mentions(rig.render(broken), "light 1: intensity must be finite"));
  broken.lights[1].intensity = 1;
  broken.lights[0].color[1] = -1;
  CHECK(log_mentions(rig.render(broken), "light 0: colour must be finite and >= 0"));
  broken.lights[0].color[1] = 1;
  broken.lights[0].range = NAN;
  CHECK(log_mentions(rig.render(broken), "light 0: range must be finite"));
  // And a good frame renders again afterwards.
  CHECK(rig.render(captured).error.empty());
}

TEST_CASE("any size: 1x1, odd sizes not divisible by the tiles, thin frames", "[tiledlights][gl][hard]") {
  Rig rig;
  const pfx::app::Scene scene = pfx::app::make_demo_scene();
  for (auto [w, h] : {std::pair{1, 1}, std::pair{97, 61}, std::pair{3, 70}, std::pair{130, 2}}) {
    INFO(w << "x" << h);
    check_modes(rig, capture(scene, w, h));
  }
}

TEST_CASE("tile sizes, grids and slice counts change nothing in the image", "[tiledlights][gl]") {
  Rig rig;
  const Captured captured = capture(pfx::app::make_demo_scene(), 50, 30);
  const auto brute = check_modes(rig, captured);
  for (const char* setting : {"tile_size=5", "tile_size=64", "cpu_tiles_x=64", "cpu_tiles_y=1", "slices=1",
                              "slices=64", "cluster_tile_size=8"}) {
    INFO(setting);
    rig.set(setting);
    for (const char* mode : {"cpu8x4", "tiled", "clustered"}) {
      rig.set(std::string("mode=") + mode);
      const Rendered r = rig.render(captured);
      REQUIRE(r.error.empty());
      require_identical(r.output, brute, captured.width);
    }
  }
}

TEST_CASE("the sqrt-colour range rule and explicit ranges", "[tiledlights][gl]") {
  Rig rig;
  rig.set("range_rule=seed");
  pfx::app::Scene scene = pfx::app::make_demo_scene();
  scene.lights[10].range = 0.5f;
  scene.lights[11].range = 15.0f;
  check_modes(rig, capture(scene, 64, 36));
}

TEST_CASE("hardware and reversed depth give the linear-depth image", "[tiledlights][gl][hard]") {
  Rig rig;
  Captured captured = capture(pfx::app::make_demo_scene(), 48, 27);
  rig.set("mode=brute");
  const auto linear = rig.render(captured).output;
  const double n = captured.frame.camera.near_plane, f = captured.frame.camera.far_plane;
  for (pfx_depth_encoding encoding : {PFX_DEPTH_HARDWARE, PFX_DEPTH_HARDWARE_REVERSED}) {
    INFO("encoding " << encoding);
    // Stored values from linear depth (standard: window z of the projection; reversed: 1 at near).
    pfx::app::Image depth;
    depth.width = captured.width;
    depth.height = captured.height;
    depth.rgba.assign(depth.pixel_count() * 4, 0.0f);
    depth.depth.resize(depth.pixel_count());
    std::vector<float> stored(captured.depth.size());
    for (size_t i = 0; i < stored.size(); ++i) {
      const double d = captured.depth[i];
      if (std::isinf(d)) stored[i] = encoding == PFX_DEPTH_HARDWARE ? 1.0f : 0.0f;
      else if (encoding == PFX_DEPTH_HARDWARE) stored[i] = float(0.5 * ((f + n) / (f - n) - 2 * f * n / ((f - n) * d)) + 0.5);
      else stored[i] = float(n * (f - d) / (d * (f - n)));
    }
    // upload_depth_texture takes rows top first.
    depth.depth = pfx::app::flip_rows(stored, captured.width, captured.height, 1);
    const uint32_t texture = pfx::app::upload_depth_texture(depth);
    Captured encoded = capture(pfx::app::make_demo_scene(), 48, 27);
    encoded.frame.depth_encoding = encoding;
    encoded.textures.depth = texture;
    encoded.depth = stored;
    // Decoding window depth in float loses precision far from the near plane (the GPU's decode
    // differs from the double reference by ~1e-3 here): the modes must still agree exactly, and
    // the image must stay within 2% of the linear-depth one.
    const auto out = check_modes(rig, encoded, false);
    double worst = 0;
    for (size_t i = 0; i < out.size(); ++i) worst = std::max(worst, std::abs(double(out[i]) - linear[i]) / (1e-2 + std::abs(linear[i])));
    CHECK(worst < 0.02);
    pfx::app::delete_texture(texture);
  }
}

TEST_CASE("a frame without the lights input is refused naming it, an orthographic camera with a message",
          "[tiledlights][gl][hard]") {
  Rig rig;
  Captured captured = capture(pfx::app::make_demo_scene(), 16, 16);
  captured.frame.inputs &= ~PFX_INPUT_LIGHTS;
  Rendered r = rig.render(captured);
  CHECK(r.error.find("lights") != std::string::npos);
  captured = capture(pfx::app::make_demo_scene(), 16, 16);
  float* p = captured.frame.camera.projection;
  p[11] = 0;
  p[15] = 1;  // orthographic: w = 1
  r = rig.render(captured);
  CHECK_FALSE(r.error.empty());
  CHECK(log_mentions(r, "not a perspective projection"));
}

TEST_CASE("frames queued back to back each see their own lights (the upload ring's fences)", "[tiledlights][gl][hard]") {
  Rig rig;
  rig.chain_timing_off();
  // Eight frames (more than the three ring buffers), each with the lights moved; rendered without
  // a read in between, then each compared with its own brute-force image.
  std::vector<Captured> frames;
  for (int f = 0; f < 8; ++f) {
    pfx::app::Scene scene = pfx::app::make_demo_scene({0, uint64_t(f + 1)});
    for (pfx_light& light : scene.lights) light.position[1] = 0.5f + 0.25f * f;
    frames.push_back(capture(scene, 48, 27));
  }
  std::vector<Captured*> pointers;
  for (Captured& c : frames) pointers.push_back(&c);
  for (const char* mode : {"cpu8x4", "tiled", "clustered", "brute"}) {
    INFO(mode);
    rig.set(std::string("mode=") + mode);
    const auto queued = rig.render_queued(pointers);
    rig.set("mode=brute");
    for (size_t f = 0; f < frames.size(); ++f) {
      INFO("frame " << f);
      require_identical(queued[f], rig.render(frames[f]).output, 48);
    }
  }
}
