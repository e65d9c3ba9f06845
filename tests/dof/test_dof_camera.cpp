// The thin-lens camera model (dof_camera) on its own, against values computed independently: the
// thin-lens CoC formula as published (lengths in mm) evaluated literally, projection matrices built
// with GLM, and the named hard cases of the camera (focus at the focal length, at 0 and at
// infinity, depth 0 and 1, near == far, the f-number's hard minimum, bad depths, degenerate
// cameras, autofocus on the sky).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "dof_camera.hpp"
#include "dof_params.hpp"

using namespace pfx_dof;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = M_PI / 180.0;

Settings defaults() {
  pfx_value values[PARAM_COUNT];
  for (uint32_t i = 0; i < PARAM_COUNT; ++i) values[i] = kParams[i].default_value;
  return settings_from(values);
}

pfx_frame frame_of(uint32_t w, uint32_t h, double fovy_deg, pfx_depth_encoding encoding, double near_plane = 0.1,
                   double far_plane = 1000) {
  pfx_frame f{};
  f.struct_size = sizeof f;
  f.width = w;
  f.height = h;
  f.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;
  f.depth_encoding = encoding;
  f.camera.fovy = static_cast<float>(fovy_deg * kDeg);
  f.camera.aspect = static_cast<float>(double(w) / double(h));
  f.camera.near_plane = static_cast<float>(near_plane);
  f.camera.far_plane = static_cast<float>(far_plane);
  return f;
}

// The thin-lens CoC, written as it is usually published (all lengths in mm), but with the horizontal field
// of view passed in: |A F (P - D) / (D (P - F))| * pixels per mm.
double seed_coc_pixels(double fovx, double sensor_mm, double width_px, double f_number, double focus_m,
                       double depth_m) {
  const double distance = focus_m * 1000.0;
  const double image_distance = (sensor_mm * 0.5) / std::tan(fovx * 0.5);
  const double focal_length = 1.0 / ((1.0 / distance) + (1.0 / image_distance));
  const double aperture = focal_length / f_number;
  const double object = depth_m * 1000.0;
  const double coc_mm = std::fabs(aperture * (focal_length * (distance - object)) / (object * (distance - focal_length)));
  return coc_mm * width_px / sensor_mm;
}

}  // namespace

TEST_CASE("fovx: the horizontal field of view is 2 atan(tan(fovy/2) aspect), not fovy * aspect",
          "[dof][camera]") {
  // Independent check: project a view-space point lying exactly on the horizontal edge of the true
  // horizontal field of view with GLM's perspective matrix: it must land on the frame's edge.
  for (double fovy_deg : {10.0, 45.0, 90.0, 120.0})
    for (double aspect : {0.5, 1.0, 16.0 / 9.0, 2.35}) {
      const double fovy = fovy_deg * kDeg;
      const double fovx = horizontal_fov(fovy, aspect);
      const glm::dmat4 projection = glm::perspective(fovy, aspect, 0.1, 100.0);
      const glm::dvec4 clip = projection * glm::dvec4(std::tan(fovx / 2) * 5.0, 0.0, -5.0, 1.0);
      INFO("fovy " << fovy_deg << " aspect " << aspect);
      CHECK(clip.x / clip.w == Approx(1.0).epsilon(1e-12));
    }
  // fovy * aspect is close only for narrow angles: 0.5% at fovy 10 x 16:9, 10% at 45
  // degrees, and at fovy 90 x 2:1 it reaches 180 degrees, where the image distance becomes zero.
  const double narrow = horizontal_fov(10 * kDeg, 16.0 / 9.0), seed_narrow = 10 * kDeg * 16.0 / 9.0;
  CHECK(std::fabs(seed_narrow / narrow - 1.0) < 0.006);
  const double normal = horizontal_fov(45 * kDeg, 16.0 / 9.0), seed_normal = 45 * kDeg * 16.0 / 9.0;
  CHECK(normal / kDeg == Approx(72.734).margin(0.001));
  CHECK(seed_normal / kDeg == Approx(80.0));
  CHECK(seed_normal / normal == Approx(1.0999).margin(0.0005));
  const double wide = horizontal_fov(90 * kDeg, 2.0);
  CHECK(wide / kDeg == Approx(126.870).margin(0.001));
  CHECK(90 * kDeg * 2.0 == Approx(M_PI));

  // What that does to the blur: at fovy 60 x 16:9 (fovx 91.5 degrees, fovy * aspect's 106.7), fovy * aspect's
  // sensor distance is 23% short, and its CoC at 1 m with focus at 10 m is 42% too small.
  Settings s = defaults();
  const pfx_frame f = frame_of(1920, 1080, 60, PFX_DEPTH_LINEAR);
  const Lens lens = make_lens(f, s, s.focus_distance);
  const double ours = -coc_pixels(lens, 1.0);
  const double seed_fovx = 60 * kDeg * 16.0 / 9.0;
  const double seeds = seed_coc_pixels(seed_fovx, 36, 1920, s.f_number, 10, 1.0);
  CHECK(ours == Approx(seed_coc_pixels(horizontal_fov(f.camera.fovy, f.camera.aspect), 36, 1920, s.f_number, 10, 1.0)));
  CHECK(std::tan(horizontal_fov(f.camera.fovy, f.camera.aspect) / 2) / std::tan(seed_fovx / 2) ==
        Approx(0.765).margin(0.001));
  CHECK(seeds / ours == Approx(0.584).margin(0.001));
}

TEST_CASE("the CoC is the thin-lens formula in pixels, signed: near negative, far positive",
          "[dof][camera]") {
  Settings s = defaults();
  for (double fovy_deg : {20.0, 45.0, 75.0})
    for (double f_number : {0.7, 1.4, 8.0})
      for (double focus : {0.5, 3.0, 10.0, 80.0})
        for (double depth : {0.3, 0.9, 2.0, 9.99, 10.0, 25.0, 400.0}) {
          s.f_number = f_number;
          s.max_coc = kMaxCocLimit;
          const pfx_frame f = frame_of(1280, 720, fovy_deg, PFX_DEPTH_LINEAR);
          const Lens lens = make_lens(f, s, focus);
          // The frame carries the camera in float: the published formula gets the same angles.
          const double fovx = 2.0 * std::atan(std::tan(0.5 * double(f.camera.fovy)) * double(f.camera.aspect));
          const double expected = seed_coc_pixels(fovx, 36, 1280, f_number, focus, depth);
          const double coc = coc_pixels(lens, depth);
          INFO("fovy " << fovy_deg << " N " << f_number << " P " << focus << " D " << depth);
          if (expected >= kMaxCocLimit) {
            CHECK(std::fabs(coc) == kMaxCocLimit);
          } else {
            CHECK(std::fabs(coc) == Approx(expected).epsilon(1e-9).margin(1e-12));
          }
          if (depth < focus) CHECK(coc <= 0.0);
          if (depth > focus) CHECK(coc >= 0.0);
        }
  // The published example's numbers: image distance 50 mm, focus 4 m: focal length about 49.4 mm.
  pfx_frame f = frame_of(1000, 1000, 0, PFX_DEPTH_LINEAR);
  f.camera.fovy = static_cast<float>(2.0 * std::atan(18.0 / 50.0));
  f.camera.aspect = 1.0f;
  const Lens seed_lens = make_lens(f, defaults(), 4.0);
  CHECK(seed_lens.image_distance_mm == Approx(50.0).epsilon(1e-6));
  CHECK(seed_lens.focal_length_mm == Approx(49.38).margin(0.01));
  CHECK(seed_lens.aperture_mm == Approx(seed_lens.focal_length_mm / 1.4));
}

TEST_CASE("every depth encoding gives the same CoC for the same scene", "[dof][camera]") {
  // The same points stored as a GPU would store them under each encoding (GLM's matrices; float
  // storage as in an R32F or depth texture), decoded by the model: the CoCs agree.
  const double n = 0.1, fovy = 45 * kDeg, aspect = 16.0 / 9.0;
  Settings s = defaults();
  s.focus_distance = 3.0;
  s.f_number = 0.5;
  s.max_coc = kMaxCocLimit;
  auto window_z = [&](const glm::dmat4& m, double depth, bool zero_to_one) {
    const glm::dvec4 clip = m * glm::dvec4(0.2 * depth, -0.1 * depth, -depth, 1.0);
    const double z = clip.z / clip.w;
    return zero_to_one ? z : 0.5 * z + 0.5;
  };
  struct Encoding {
    const char* name;
    pfx_depth_encoding encoding;
    double far_plane;
    glm::dmat4 matrix;
    bool zero_to_one;
  };
  glm::dmat4 reversed_infinite(0.0);  // 1 at near, 0 at infinity: z_clip = near, w = -z_view
  reversed_infinite[0][0] = 1.0 / (std::tan(fovy / 2) * aspect);
  reversed_infinite[1][1] = 1.0 / std::tan(fovy / 2);
  reversed_infinite[2][3] = -1.0;
  reversed_infinite[3][2] = n;
  const Encoding encodings[] = {
      {"hardware, finite far", PFX_DEPTH_HARDWARE, 1000, glm::perspective(fovy, aspect, n, 1000.0), false},
      {"hardware, infinite far", PFX_DEPTH_HARDWARE, kInf, glm::infinitePerspective(fovy, aspect, n), false},
      {"reversed, finite far", PFX_DEPTH_HARDWARE_REVERSED, 1000, glm::perspectiveRH_ZO(fovy, aspect, 1000.0, n), true},
      {"reversed, infinite far", PFX_DEPTH_HARDWARE_REVERSED, kInf, reversed_infinite, true},
  };
  for (double depth : {0.15, 0.5, 1.0, 2.9, 3.0, 3.1, 7.0, 40.0, 300.0}) {
    pfx_frame linear = frame_of(1920, 1080, 45, PFX_DEPTH_LINEAR);
    const double expected = coc_pixels(make_lens(linear, s, s.focus_distance), view_depth(linear, float(depth)));
    for (const Encoding& e : encodings) {
      const pfx_frame f = frame_of(1920, 1080, 45, e.encoding, n, e.far_plane);
      const float stored = static_cast<float>(window_z(e.matrix, depth, e.zero_to_one));
      const double coc = coc_pixels(make_lens(f, s, s.focus_distance), view_depth(f, stored));
      INFO(e.name << ", depth " << depth << " stored " << stored);
      // Float storage of hardware depth loses precision with distance: 0.002 px at 300 m here.
      CHECK(coc == Approx(expected).margin(0.01));
    }
  }
}

TEST_CASE("focus distance equal to the focal length gives a finite CoC (the formula as published divides by zero there)",
          "[dof][camera][hard]") {
  Settings s = defaults();
  const pfx_frame f = frame_of(1920, 1080, 45, PFX_DEPTH_LINEAR);
  const Lens at_ten = make_lens(f, s, 10.0);
  // Focus at the distance the 10 m lens's focal length names: the formula's P - F is then zero.
  const double p = at_ten.focal_length_mm / 1000.0;
  const Lens lens = make_lens(f, s, p);
  CHECK(std::isfinite(lens.coc_scale));
  for (double depth : {0.01, p, 0.5, 10.0, kInf}) {
    const double coc = coc_pixels(lens, depth);
    INFO("depth " << depth);
    CHECK(std::isfinite(coc));
    CHECK(std::fabs(coc) <= s.max_coc);
  }
  CHECK(coc_pixels(lens, p) == Approx(0.0).margin(1e-9));
  CHECK(coc_pixels(lens, kInf) == s.max_coc);  // everything beyond is far out of focus
}

TEST_CASE("focus at 0 is clamped to 1 mm and focus at infinity leaves the sky sharp", "[dof][camera][hard]") {
  Settings s = defaults();
  const pfx_frame f = frame_of(1920, 1080, 45, PFX_DEPTH_LINEAR);
  const Lens zero = make_lens(f, s, 0.0);
  CHECK(zero.focus_distance_m == kMinFocusDistance);
  CHECK(coc_pixels(zero, 1.0) == s.max_coc);
  CHECK(coc_pixels(zero, kMinFocusDistance) == Approx(0.0).margin(1e-9));

  const Lens infinity = make_lens(f, s, kInf);
  CHECK(infinity.focus_distance_m == kMaxFocusDistance);
  CHECK(std::fabs(coc_pixels(infinity, kInf)) < 1e-6);
  // Focused at infinity everything is in front: CoC = -C / D (the thin-lens formula in the limit).
  CHECK(coc_pixels(infinity, 100.0) == Approx(-infinity.coc_scale / 100.0).epsilon(1e-6));
  CHECK(coc_pixels(infinity, 100.0) < 0.0);
  // NaN asks for the settings' distance.
  CHECK(make_lens(f, s, std::nan("")).focus_distance_m == s.focus_distance);
}

TEST_CASE("stored depth exactly 0 and 1 decode to the near plane and to the far plane or the sky",
          "[dof][camera][hard]") {
  Settings s = defaults();
  s.max_coc = kMaxCocLimit;
  const pfx_frame hw = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE, 0.5, 200);
  const pfx_frame hw_inf = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE, 0.5, kInf);
  const pfx_frame rev = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE_REVERSED, 0.5, 200);
  const pfx_frame rev_inf = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE_REVERSED, 0.5, kInf);
  CHECK(view_depth(hw, 0.0) == Approx(0.5));
  CHECK(view_depth(hw, 1.0) == Approx(200.0));
  CHECK(view_depth(hw_inf, 1.0) == kInf);
  CHECK(view_depth(rev, 1.0) == Approx(0.5));
  CHECK(view_depth(rev, 0.0) == Approx(200.0));
  CHECK(view_depth(rev_inf, 0.0) == kInf);
  const Lens lens = make_lens(hw, s, 10.0);
  CHECK(coc_pixels(lens, view_depth(hw_inf, 1.0)) == Approx(lens.coc_scale / 10.0));  // sky: the far limit C/P
  CHECK(coc_pixels(lens, view_depth(hw, 0.0)) == Approx(lens.coc_scale * (0.1 - 2.0)));
  // Linear depth 0 is nearer than any lens can see.
  const pfx_frame linear = frame_of(64, 64, 45, PFX_DEPTH_LINEAR);
  CHECK(coc_pixels(make_lens(linear, s, 10.0), view_depth(linear, 0.0)) == -s.max_coc);
}

TEST_CASE("near == far decodes every hardware depth to that plane: one finite CoC", "[dof][camera][hard]") {
  Settings s = defaults();
  const pfx_frame f = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE, 2.0, 2.0);
  CHECK(camera_problem(f).empty());
  const Lens lens = make_lens(f, s, 10.0);
  for (double stored : {0.0, 0.25, 0.5, 1.0}) {
    CHECK(view_depth(f, stored) == Approx(2.0));
    CHECK(coc_pixels(lens, view_depth(f, stored)) == Approx(coc_pixels(lens, 2.0)));
  }
  const pfx_frame r = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE_REVERSED, 2.0, 2.0);
  for (double stored : {0.0, 0.5, 1.0}) CHECK(view_depth(r, stored) == Approx(2.0));
}

TEST_CASE("the f-number at its hard minimum clamps the CoC at the maximum, both signs", "[dof][camera][hard]") {
  Settings s = defaults();
  s.f_number = kMinFNumber;
  const pfx_frame f = frame_of(1920, 1080, 45, PFX_DEPTH_LINEAR);
  const Lens lens = make_lens(f, s, 10.0);
  CHECK(coc_pixels(lens, 1.0) == -s.max_coc);
  CHECK(coc_pixels(lens, kInf) == s.max_coc);
  CHECK(coc_pixels(lens, 10.0) == Approx(0.0).margin(1e-9));
}

TEST_CASE("NaN, infinite and negative depths give documented finite CoCs", "[dof][camera][hard]") {
  Settings s = defaults();
  const pfx_frame f = frame_of(1920, 1080, 45, PFX_DEPTH_LINEAR);
  const Lens lens = make_lens(f, s, 10.0);
  CHECK(coc_pixels(lens, std::nan("")) == 0.0);
  CHECK(coc_pixels(lens, kInf) == Approx(lens.coc_scale * 0.1));
  CHECK(coc_pixels(lens, -kInf) == -s.max_coc);
  CHECK(coc_pixels(lens, -3.0) == -s.max_coc);
  // A stored NaN stays NaN through decoding, so it reaches the same rule.
  const pfx_frame hw = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE);
  CHECK(coc_pixels(lens, view_depth(hw, std::nan(""))) == 0.0);
}

TEST_CASE("degenerate cameras are named, not decoded", "[dof][camera][hard]") {
  pfx_frame f = frame_of(64, 64, 45, PFX_DEPTH_HARDWARE);
  CHECK(camera_problem(f).empty());
  for (float fovy : {0.0f, -1.0f, static_cast<float>(M_PI), 4.0f, std::nanf("")}) {
    pfx_frame g = f;
    g.camera.fovy = fovy;
    CHECK_THAT(camera_problem(g), Catch::Contains("field of view"));
  }
  for (float aspect : {0.0f, -1.0f, std::nanf(""), HUGE_VALF}) {
    pfx_frame g = f;
    g.camera.aspect = aspect;
    CHECK_THAT(camera_problem(g), Catch::Contains("aspect"));
  }
  pfx_frame g = f;
  g.camera.near_plane = 0.0f;
  CHECK_THAT(camera_problem(g), Catch::Contains("near plane"));
  g = f;
  g.camera.far_plane = 0.05f;
  CHECK_THAT(camera_problem(g), Catch::Contains("far plane"));
  // Linear depth needs no planes.
  g = frame_of(64, 64, 45, PFX_DEPTH_LINEAR);
  g.camera.near_plane = 0.0f;
  CHECK(camera_problem(g).empty());
}

TEST_CASE("autofocus reads the depth under the focus point, the sky focuses at infinity", "[dof][camera][hard]") {
  Settings s = defaults();
  s.autofocus = AUTOFOCUS_POINT;
  const uint32_t w = 5, h = 3;
  std::vector<float> depth(w * h, 7.0f);
  uint32_t x = 0, y = 0;
  focus_texel(w, h, s, &x, &y);
  CHECK(x == 2);
  CHECK(y == 1);
  s.focus_point[0] = 0.0;
  s.focus_point[1] = 0.0;  // top-left: GL row h - 1
  focus_texel(w, h, s, &x, &y);
  CHECK((x == 0 && y == 2));
  s.focus_point[0] = 1.0;
  s.focus_point[1] = 1.0;  // bottom-right, clamped inside
  focus_texel(w, h, s, &x, &y);
  CHECK((x == 4 && y == 0));
  focus_texel(1, 1, s, &x, &y);
  CHECK((x == 0 && y == 0));

  const pfx_frame f = frame_of(w, h, 45, PFX_DEPTH_LINEAR);
  depth[0 * w + 4] = 3.5f;
  CHECK(focus_distance(f, s, depth.data()) == Approx(3.5));
  depth[0 * w + 4] = HUGE_VALF;
  CHECK(focus_distance(f, s, depth.data()) == kMaxFocusDistance);
  const Lens sky = make_lens(f, s, focus_distance(f, s, depth.data()));
  CHECK(std::fabs(coc_pixels(sky, kInf)) < 1e-6);
  depth[0 * w + 4] = std::nanf("");
  CHECK(focus_distance(f, s, depth.data()) == s.focus_distance);
  depth[0 * w + 4] = 0.0f;
  CHECK(focus_distance(f, s, depth.data()) == kMinFocusDistance);
  s.autofocus = AUTOFOCUS_OFF;
  CHECK(focus_distance(f, s, depth.data()) == s.focus_distance);
}
