// The CPU references on their own: the scatter (PFX_REFERENCE_IDEAL for image inputs) and the
// lens-sampled ground truth of the synthetic scene, against what optics says they must do.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "dof_camera.hpp"
#include "dof_params.hpp"
#include "reference/dof_scatter_reference.hpp"
#include "reference/dof_scene.hpp"

using namespace pfx_dof;

namespace {

pfx_frame scene_frame(int w, int h) {
  pfx_frame f{};
  f.struct_size = sizeof f;
  f.width = static_cast<uint32_t>(w);
  f.height = static_cast<uint32_t>(h);
  f.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;
  f.depth_encoding = PFX_DEPTH_LINEAR;
  f.camera.fovy = static_cast<float>(45 * M_PI / 180);
  f.camera.aspect = static_cast<float>(double(w) / h);
  f.camera.near_plane = 0.1f;
  f.camera.far_plane = 1000.0f;
  return f;
}

Settings scene_settings(double f_number) {
  Settings s;
  s.focus_distance = kSceneFocusDistance;
  s.f_number = f_number;
  s.max_coc = kMaxCocLimit;
  return s;
}

double sum_rgb(const std::vector<float>& rgba) {
  double s = 0;
  for (size_t i = 0; i < rgba.size(); ++i)
    if (i % 4 != 3) s += rgba[i];
  return s;
}

}  // namespace

TEST_CASE("scatter reference: a frame in focus is returned as it was", "[dof][reference]") {
  const pfx_frame f = scene_frame(40, 30);
  std::vector<float> color(40 * 30 * 4), depth(40 * 30, 5.0f), out(color.size());
  for (size_t i = 0; i < color.size(); ++i) color[i] = float(i % 13) * 0.25f - 1.0f;
  evaluate_scatter_reference(scene_settings(1.4), f, color.data(), depth.data(), out.data());
  for (size_t i = 0; i < color.size(); ++i) REQUIRE(out[i] == color[i]);
}

TEST_CASE("scatter reference: a bright pixel spreads over a disc of the CoC's diameter, energy kept",
          "[dof][reference]") {
  const int w = 81, h = 61;
  const pfx_frame f = scene_frame(w, h);
  Settings s = scene_settings(0.05);
  std::vector<float> color(w * h * 4, 0.0f), depth(w * h, 20.0f), out(color.size());
  color[(30 * w + 40) * 4] = 1000.0f;
  const double coc = coc_pixels(make_lens(f, s, s.focus_distance), 20.0);
  REQUIRE(coc > 5.0);
  evaluate_scatter_reference(s, f, color.data(), depth.data(), out.data());
  CHECK(sum_rgb(out) == Approx(1000.0).epsilon(1e-6));  // float output
  // Inside the disc, away from its antialiased rim: flat; outside: nothing.
  const double inside = out[(30 * w + 40) * 4];
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = std::hypot(x - 40.0, y - 30.0), v = out[(y * w + x) * 4];
      if (d < coc / 2 - 0.5) REQUIRE(v == Approx(inside));
      if (d > coc / 2 + 0.5) REQUIRE(v == 0.0);
    }
  CHECK(inside == Approx(1000.0 / (M_PI * coc * coc / 4)).epsilon(0.05));
}

TEST_CASE("scatter reference: a blurred foreground covers the sharp background, front to back",
          "[dof][reference]") {
  const int w = 64, h = 32;
  const pfx_frame f = scene_frame(w, h);
  Settings s = scene_settings(0.05);  // the foreground's CoC: about -17 px
  std::vector<float> color(w * h * 4, 0.0f), depth(w * h, 5.0f), out(color.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 32; ++x) {
      color[(y * w + x) * 4] = 1.0f;  // the foreground's red, at 1 m
      depth[y * w + x] = 1.0f;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 32; x < w; ++x) color[(y * w + x) * 4 + 1] = 1.0f;  // the background's green, in focus
  evaluate_scatter_reference(s, f, color.data(), depth.data(), out.data());
  const int row = 16;
  auto red = [&](int x) { return out[(row * w + x) * 4]; };
  auto green = [&](int x) { return out[(row * w + x) * 4 + 1]; };
  // Just past the edge about half the pixel is the foreground's; it fades to none at its radius.
  CHECK(red(32) > 0.3);
  CHECK(red(32) < 0.6);
  CHECK(red(32) + green(32) == Approx(1.0));
  CHECK(red(40) < red(34));
  // Inside the foreground nothing of the background shows: it is behind.
  CHECK(green(20) == 0.0f);
}

TEST_CASE("lens truth: a pinhole-sized aperture gives the pinhole frame", "[dof][reference]") {
  const pfx_frame f = scene_frame(64, 36);
  const SceneFrame pinhole = render_pinhole(f);
  const std::vector<float> truth = render_lens_truth(f, 0.0, kSceneFocusDistance, 16);
  // The rays are the pinhole's up to rounding (they aim at a point on the focus plane instead of
  // along a direction), which can move a hit across a texture's edge in a rare pixel.
  size_t differ = 0;
  for (size_t i = 0; i < truth.size(); ++i)
    if (i % 4 != 3) differ += std::fabs(truth[i] - pinhole.rgba[i]) > 1e-6;
  CHECK(differ <= truth.size() / 200);
}

TEST_CASE("lens truth: the plane in focus stays sharp, and a bright point blurs to the CoC's diameter",
          "[dof][reference]") {
  const int w = 160, h = 90;
  const pfx_frame f = scene_frame(w, h);
  const Settings s = scene_settings(0.25);
  const Lens lens = make_lens(f, s, s.focus_distance);
  const SceneFrame pinhole = render_pinhole(f);
  const std::vector<float> truth = render_lens_truth(f, lens.aperture_mm / 1000.0, lens.focus_distance_m, 256);
  // The subject's front face lies on the plane in focus: every lens ray of its pixels meets it at the
  // same point, unless something nearer blocks part of the lens.
  // The 9x9 neighbourhood must stay inside the frame: start and stop 4 pixels from the edges.
  int sharp = 0;
  for (int y = 4; y < h - 4; ++y)
    for (int x = 4; x < w - 4; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      bool interior = true;
      for (int v = -4; v <= 4; ++v)
        for (int u = -4; u <= 4; ++u)
          interior &= pinhole.object[(y + v) * w + (x + u)] == OBJECT_SUBJECT &&
                      pinhole.depth[(y + v) * w + (x + u)] == Approx(kSceneFocusDistance);
      if (!interior) continue;
      ++sharp;
      for (int k = 0; k < 3; ++k) REQUIRE(truth[i * 4 + k] == Approx(pinhole.rgba[i * 4 + k]).margin(1e-6));
    }
  CHECK(sharp > 50);
  // The wall light at 40 m: its bokeh spans the CoC there (geometry and formula agree).
  const double coc = coc_pixels(lens, 39.9);
  int x0 = w, x1 = -1, row = -1;
  double brightest = 0;
  for (int y = 0; y < h; ++y)
    for (int x = w / 2; x < w; ++x)
      if (truth[(y * w + x) * 4 + 2] > brightest) brightest = truth[(y * w + x) * 4 + 2], row = y;
  for (int x = w / 2; x < w; ++x)
    if (truth[(row * w + x) * 4 + 2] > 0.18 + 0.5 * (brightest - 0.18)) x0 = std::min(x0, x), x1 = std::max(x1, x);
  INFO("CoC " << coc << " px, bokeh from " << x0 << " to " << x1 << " on row " << row);
  CHECK(x1 - x0 + 1 == Approx(coc).margin(2.0));
}
