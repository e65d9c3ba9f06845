// The GL-free parts of tiledlights: light ranges, light checks, the sub-frustum grid of tiled shading
// (conservative against points projected through the camera's own matrix), the references.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "cpu_culling.hpp"
#include "light_set.hpp"
#include "list_bound.hpp"
#include "reference/light_shading.hpp"
#include "tiledlights_params.hpp"
#include "view_frustum.hpp"

using namespace pfx_tiledlights;

namespace {

pfx_light light_at(double x, double y, double z, float intensity, float range = 0) {
  pfx_light l{};
  l.position[0] = float(x);
  l.position[1] = float(y);
  l.position[2] = float(z);
  l.color[0] = 1;
  l.color[1] = 0.5f;
  l.color[2] = 0.25f;
  l.intensity = intensity;
  l.range = range;
  return l;
}

// A frame with an identity view (camera at the origin looking down -Z) and a perspective
// projection, column-major, built here from its definition.
pfx_frame frame_with(int width, int height, const std::vector<pfx_light>& lights, double fovy = 1.0) {
  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = uint32_t(width);
  frame.height = uint32_t(height);
  frame.inputs = PFX_INPUT_LIGHTS;
  for (int i = 0; i < 4; ++i) frame.camera.view[i * 5] = 1;
  const double f = 1 / std::tan(fovy / 2), aspect = double(width) / height, n = 0.1, far = 100;
  float* p = frame.camera.projection;
  p[0] = float(f / aspect);
  p[5] = float(f);
  p[10] = float(-(far + n) / (far - n));
  p[11] = -1;
  p[14] = float(-2 * far * n / (far - n));
  frame.camera.near_plane = float(n);
  frame.camera.far_plane = float(far);
  frame.camera.fovy = float(fovy);
  frame.camera.aspect = float(aspect);
  frame.lights = lights.data();
  frame.light_count = uint32_t(lights.size());
  frame.light_struct_size = sizeof(pfx_light);
  return frame;
}

}  // namespace

TEST_CASE("ranges: the cutoff rule ends where the light falls to the cutoff, the sqrt-colour rule's is 3 sqrt(peak)", "[tiledlights]") {
  const pfx_light l = light_at(0, 0, 0, 4.0f);  // peak = 4 * max(1, 0.5, 0.25) = 4
  const double r = light_range(l, RANGE_CUTOFF, 0.05);
  CHECK(4.0 / (1 + r * r) == Approx(0.05));
  CHECK(light_range(l, RANGE_SEED, 0.05) == Approx(6.0));
  CHECK(light_range(light_at(0, 0, 0, 4.0f, 2.5f), RANGE_CUTOFF, 0.05) == 2.5);  // explicit wins
  CHECK(light_range(light_at(0, 0, 0, 0.0f), RANGE_CUTOFF, 0.05) == 0);
  CHECK(light_range(light_at(0, 0, 0, 0.0f), RANGE_SEED, 0.05) == 0);
  CHECK(light_range(light_at(0, 0, 0, 0.04f), RANGE_CUTOFF, 0.05) == 0);  // never above the cutoff
}

TEST_CASE("prepare_lights names the first bad light and drops those that reach nothing", "[tiledlights][hard]") {
  Settings settings;
  std::vector<pfx_light> lights = {light_at(0, 0, -5, 1), light_at(1, 0, -5, 0), light_at(2, 0, -5, 1)};
  pfx_frame frame = frame_with(8, 8, lights);
  LightSet set;
  std::string error;
  REQUIRE(prepare_lights(frame, settings, &set, &error));
  CHECK(set.lights.size() == 2);
  CHECK(set.unreachable == 1);
  CHECK(set.source == std::vector<uint32_t>{0, 2});
  CHECK(set.lights[1].view[0] == 2.0f);
  CHECK(set.lights[1].cull_radius > set.lights[1].range);

  lights[2].position[0] = NAN;
  frame = frame_with(8, 8, lights);
  CHECK_FALSE(prepare_lights(frame, settings, &set, &error));
  CHECK(error == "light 2: position is not finite (nan, 0, -5)");
  lights[2].position[0] = 0;
  lights[0].intensity = -1;
  frame = frame_with(8, 8, lights);
  CHECK_FALSE(prepare_lights(frame, settings, &set, &error));
  CHECK(error.find("light 0: intensity") == 0);
  frame.light_struct_size = 8;
  CHECK_FALSE(prepare_lights(frame, settings, &set, &error));
  CHECK(error.find("light_struct_size") != std::string::npos);
}

TEST_CASE("a pixel's tile by the shader's integer rule is the tile whose pixel span holds it", "[tiledlights]") {
  for (int size : {1, 2, 7, 97, 720, 1080, 1917})
    for (int count : {1, 3, 4, 8, 16, 33, 256}) {
      for (int pixel = 0; pixel < size; ++pixel) {
        const int tile = static_cast<int>(static_cast<long long>(pixel) * count / size);
        REQUIRE(grid_tile_first_pixel(tile, count, size) <= pixel);
        REQUIRE(pixel < grid_tile_first_pixel(tile + 1, count, size));
      }
      REQUIRE(grid_tile_first_pixel(count, count, size) == size);
    }
}

TEST_CASE("the tile grid's culling is conservative: every light reaching a point is in its tile's list", "[tiledlights]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (auto [w, h, gx, gy] : {std::tuple{1280, 720, 8, 4}, std::tuple{97, 61, 8, 4}, std::tuple{1, 1, 8, 4},
                              std::tuple{640, 360, 40, 23}}) {
    INFO(w << "x" << h << " grid " << gx << "x" << gy);
    std::vector<pfx_light> lights;
    for (int i = 0; i < 300; ++i)
      lights.push_back(light_at(unit(random) * 40 - 20, unit(random) * 30 - 15, -unit(random) * 60 + 5,
                                float(0.1 + 4 * unit(random))));
    const pfx_frame frame = frame_with(w, h, lights, 0.9);
    Settings settings;
    LightSet set;
    std::string error;
    REQUIRE(prepare_lights(frame, settings, &set, &error));
    Perspective perspective;
    REQUIRE(perspective_of(frame.camera, &perspective, &error));
    std::vector<uint32_t> all(set.lights.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    const std::vector<uint32_t> visible = lights_in_view(set, perspective, w, h, 0.1, 100);
    GridLists grid;
    REQUIRE(cull_grid(set, visible, perspective, w, h, gx, gy, &grid));
    for (size_t t = 0; t < size_t(gx) * gy; ++t)
      for (uint32_t k = 1; k < grid.heads[t * 2 + 1]; ++k)
        REQUIRE(grid.indices[grid.heads[t * 2] + k - 1] < grid.indices[grid.heads[t * 2] + k]);  // sorted

    // Random points in view, projected through the projection matrix itself.
    const float* m = frame.camera.projection;
    int reached = 0;
    for (int s = 0; s < 4000; ++s) {
      const double depth = 0.1 + 60 * unit(random);
      const double x = (unit(random) * 2 - 1) * depth * 1.2, y = (unit(random) * 2 - 1) * depth * 0.6;
      const double clip_x = m[0] * x + m[8] * -depth, clip_y = m[5] * y + m[9] * -depth, clip_w = depth;
      const double px = (clip_x / clip_w * 0.5 + 0.5) * w, py = (clip_y / clip_w * 0.5 + 0.5) * h;
      if (px < 0 || py < 0 || px >= w || py >= h) continue;
      const int tile = int(int(py) * static_cast<long long>(gy) / h) * gx + int(int(px) * static_cast<long long>(gx) / w);
      // The shader's point is the pixel centre's ray at this depth: use the pixel centre.
      const double cx = (std::floor(px) + 0.5) / w * 2 - 1, cy = (std::floor(py) + 0.5) / h * 2 - 1;
      const double p[3] = {cx / m[0] * depth, cy / m[5] * depth, -depth};
      for (uint32_t k = 0; k < visible.size(); ++k) {
        const GpuLight& light = set.lights[visible[k]];
        const double d = std::sqrt(std::pow(light.view[0] - p[0], 2) + std::pow(light.view[1] - p[1], 2) +
                                   std::pow(light.view[2] - p[2], 2));
        if (d >= light.range) continue;
        ++reached;
        const uint32_t* first = &grid.indices[0] + grid.heads[tile * 2];
        INFO("point " << p[0] << "," << p[1] << "," << p[2] << " light " << visible[k] << " tile " << tile);
        REQUIRE(std::find(first, first + grid.heads[tile * 2 + 1], k) != first + grid.heads[tile * 2 + 1]);
      }
      // And a light that reaches the point but was not "in view" would be a culling bug.
      for (uint32_t i = 0; i < set.lights.size(); ++i) {
        const GpuLight& light = set.lights[i];
        const double d = std::sqrt(std::pow(light.view[0] - p[0], 2) + std::pow(light.view[1] - p[1], 2) +
                                   std::pow(light.view[2] - p[2], 2));
        if (d < light.range) REQUIRE(std::find(visible.begin(), visible.end(), i) != visible.end());
      }
    }
    if (w > 1) CHECK(reached > 100);
  }
}

TEST_CASE("the grid culls: at 1280x720 with 8x4 tiles most lights reach few tiles", "[tiledlights]") {
  std::vector<pfx_light> lights;
  for (int i = 0; i < 400; ++i) lights.push_back(light_at((i % 20) * 2 - 19, -1, -(i / 20) * 2 - 3, 1.0f));
  const pfx_frame frame = frame_with(1280, 720, lights);
  Settings settings;
  LightSet set;
  std::string error;
  REQUIRE(prepare_lights(frame, settings, &set, &error));
  Perspective perspective;
  REQUIRE(perspective_of(frame.camera, &perspective, &error));
  const auto visible = lights_in_view(set, perspective, 1280, 720, 0.1, 100);
  CHECK(visible.size() < set.lights.size());  // lights off to the sides are dropped
  GridLists grid;
  REQUIRE(cull_grid(set, visible, perspective, 1280, 720, 8, 4, &grid));
  CHECK(grid.stats.lists == 32);
  CHECK(grid.stats.mean_length() < 0.5 * visible.size());
  CHECK(grid.stats.entries == uint64_t(grid.indices.size()));
}

TEST_CASE("the list bound is at least every tile and cluster a light's sphere touches, and not far more",
          "[tiledlights]") {
  // Lights in front of, around and behind a 1280x720 camera, of every size.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> across(-30, 30), depth(-80, 5), intensity(0.2, 40);
  std::vector<pfx_light> lights;
  for (int i = 0; i < 300; ++i) lights.push_back(light_at(across(random), across(random) / 2, depth(random), float(intensity(random))));
  const int w = 1280, h = 720, tile = 64, slices = 16;
  const pfx_frame frame = frame_with(w, h, lights);
  Settings settings;
  LightSet set;
  std::string error;
  REQUIRE(prepare_lights(frame, settings, &set, &error));
  Perspective perspective;
  REQUIRE(perspective_of(frame.camera, &perspective, &error));
  const auto visible = lights_in_view(set, perspective, w, h, 0.1, 100);
  REQUIRE(visible.size() > 100);
  // Independently: every tile's own four planes against each sphere, and the slices of depth
  // [log-spaced from near 0.1 to far 100] the sphere's depth range meets.
  uint64_t touched = 0, touched_slices = 0;
  for (uint32_t index : visible) {
    const GpuLight& light = set.lights[index];
    const double c[3] = {light.view[0], light.view[1], light.view[2]};
    int first = slices, last = -1;
    for (int s = 0; s < slices; ++s) {
      const double z0 = 0.1 * std::pow(1000.0, double(s) / slices), z1 = 0.1 * std::pow(1000.0, double(s + 1) / slices);
      if (-c[2] + light.cull_radius >= (s == 0 ? 0.0 : z0) && -c[2] - light.cull_radius <= (s == slices - 1 ? 1e30 : z1)) {
        first = std::min(first, s);
        last = s;
      }
    }
    for (int y = 0; y < h; y += tile)
      for (int x = 0; x < w; x += tile)
        if (sphere_touches(side_planes(perspective, w, h, x, std::min(x + tile, w), y, std::min(y + tile, h)), c,
                           light.cull_radius)) {
          ++touched;
          touched_slices += uint64_t(std::max(0, last - first + 1));
        }
  }
  ListGrid grid;
  grid.width = w;
  grid.height = h;
  grid.tile_size = tile;
  const uint64_t tiles_bound = list_entries_bound(set, visible, perspective, grid);
  CHECK(tiles_bound >= touched);
  CHECK(tiles_bound <= touched + touched / 4);  // the margin adds a few edge tiles, no more
  grid.slices = slices;
  grid.slice_near = 0.1;
  grid.slice_far = 100;
  const uint64_t clusters_bound = list_entries_bound(set, visible, perspective, grid);
  CHECK(clusters_bound >= touched_slices);
  CHECK(clusters_bound <= 4 * touched_slices);  // a slice either side, at most
}

TEST_CASE("references: one light at a known point, the window, and the ideal sum", "[tiledlights]") {
  // A 1x1 frame looking down -Z at a surface 2 m away facing the camera; a light 1 m in front of it.
  std::vector<pfx_light> lights = {light_at(0, 0, -1, 2.0f)};
  const pfx_frame frame_linear = [&] {
    pfx_frame f = frame_with(1, 1, lights);
    f.depth_encoding = PFX_DEPTH_LINEAR;
    return f;
  }();
  const float color[4] = {0.1f, 0.2f, 0.3f, 1}, depth[1] = {2.0f}, normal[4] = {0, 0, 1, 0},
              albedo[4] = {0.5f, 0.5f, 0.5f, 1}, emissive[4] = {3, 3, 3, 1};
  GBufferImages images{color, depth, normal, albedo, emissive};
  Settings settings;  // cutoff 0.05: range sqrt(2 / 0.05 - 1) = 6.24 m: the point is well inside
  float out[4];
  std::string error;
  REQUIRE(shade_reference(frame_linear, settings, images, true, out, &error));
  // d = 1, N.L = 1: radiance (2, 1, 0.5) / 2 = (1, 0.5, 0.25), times albedo 0.5, plus the colour.
  CHECK(out[0] == Approx(0.1 + 0.5));
  CHECK(out[1] == Approx(0.2 + 0.25));
  CHECK(out[2] == Approx(0.3 + 0.125));
  CHECK(out[3] == 1.0f);
  settings.base = BASE_EMISSIVE;
  REQUIRE(shade_reference(frame_linear, settings, images, true, out, &error));
  CHECK(out[0] == Approx(3 + 0.5));
  // A range that puts the point in the window: 1 - smoothstep(0.75, 1, d) at d = 1 / 1.1.
  settings.base = BASE_COLOR;
  lights[0].range = 1.1f;
  REQUIRE(shade_reference(frame_linear, settings, images, true, out, &error));
  const double t = (1 - 0.75 * 1.1) / (0.25 * 1.1), window = 1 - t * t * (3 - 2 * t);
  CHECK(out[0] == Approx(0.1 + 0.5 * window).epsilon(1e-6));
  // The ideal sum ignores the range.
  REQUIRE(shade_reference(frame_linear, settings, images, false, out, &error));
  CHECK(out[0] == Approx(0.6));
  // No geometry: the colour passes.
  const float sky[1] = {INFINITY};
  images.depth = sky;
  REQUIRE(shade_reference(frame_linear, settings, images, true, out, &error));
  CHECK(out[0] == 0.1f);
}
