// The "seed" mode on the GPU against its CPU model (PFX_REFERENCE_MODEL), and what the disk mode's
// algorithm does that the tests pin down: in-focus pixels untouched, blur only past 1 px.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "dof_rig.hpp"

using namespace dof_test;

namespace {

// The GPU output must equal the model within, per pixel and channel,
//
//   2^-7 L + 2^-10 M + 2^-9 |model| + 1e-5
//
// L and M: the range and the largest magnitude of the (safe) input within the reach of the taps
// (half the CoC plus two pixels for the half-size copy and its filter). Why: GL_LINEAR weights are
// computed in fixed point with 8 fractional bits (a tap off by 2^-8 of the spread of the texels it
// mixes, per axis: 2^-7 L); the half-size copy is stored in half floats (2^-11 relative, 2^-10 if a
// GPU rounds toward zero: 2^-10 M); the output is stored in half floats (2^-9 |model| with margin).
// A wrong tap, size or CoC moves the result by far more (the test below shows a 10% f-number error
// failing).
double worst_ratio(const Rendered& r, double max_coc) {
  const int w = r.input.width, h = r.input.height;
  const int reach = static_cast<int>(std::ceil(max_coc / 2)) + 3;
  double worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) {
        double lo = HUGE_VAL, hi = -HUGE_VAL, big = 0;
        for (int v = std::max(0, y - reach); v <= std::min(h - 1, y + reach); ++v)
          for (int u = std::max(0, x - reach); u <= std::min(w - 1, x + reach); ++u) {
            double c = r.input.at(u, v)[k];
            c = std::isnan(c) ? 0.0 : std::clamp(c, -65504.0, 65504.0);
            lo = std::min(lo, c), hi = std::max(hi, c), big = std::max(big, std::fabs(c));
          }
        const size_t i = (static_cast<size_t>(y) * w + x) * 4 + k;
        const double m = r.model[i], o = r.output[i];
        const double tolerance = std::ldexp(hi - lo, -7) + std::ldexp(big, -10) + std::ldexp(std::fabs(m), -9) + 1e-5;
        worst = std::max(worst, std::isfinite(o) ? std::fabs(o - m) / tolerance : HUGE_VAL);
      }
  return worst;
}

void require_matches_model(const Rendered& r, double max_coc = 32) {
  const double worst = worst_ratio(r, max_coc);
  INFO(r.input.width << "x" << r.input.height << ": worst error / tolerance = " << worst);
  if (std::getenv("DOF_TEST_VERBOSE")) std::fprintf(stderr, "%dx%d worst %.4f\n", r.input.width, r.input.height, worst);
  REQUIRE(worst <= 1.0);
}

Rig& seed_rig() { return shared_rig("seed"); }

}  // namespace

TEST_CASE("seed mode matches its CPU model on a frame with near, far and in-focus parts", "[dof][seed]") {
  Rig& rig = seed_rig();
  for (const auto& size : {std::pair{96, 64}, std::pair{37, 23}, std::pair{160, 90}}) {
    const Rendered r = rig.render(scene(size.first, size.second));
    CHECK(r.passes == 3);
    require_matches_model(r);
  }
}

TEST_CASE("seed mode leaves pixels whose CoC is at most 1 px exactly as they were", "[dof][seed]") {
  Rig& rig = seed_rig();
  const Frame f = scene(96, 64, 5.0);
  const Rendered r = rig.render(f);
  int in_focus = 0, blurred = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t i = (static_cast<size_t>(y) * f.width + x) * 4;
      if (f.depth[i / 4] == 5.0f) {
        ++in_focus;
        for (int k = 0; k < 4; ++k) REQUIRE(r.output[i + k] == r.input.rgba[i + k]);
      } else if (r.output[i] != r.input.rgba[i]) {
        ++blurred;
      }
    }
  CHECK(in_focus > 100);
  CHECK(blurred > 1000);
}

TEST_CASE("the disk-mode (seed) model comparison catches a 10% f-number error", "[dof][seed]") {
  Rig& rig = seed_rig();
  const Frame f = scene(96, 64);
  Rendered r = rig.render(f);
  rig.set("dof.f_number=0.11");
  r.model = reference(rig, r.input, PFX_REFERENCE_MODEL);
  CHECK(worst_ratio(r, 32) > 2.0);
}

TEST_CASE("seed mode: every depth encoding and a real depth texture give the same image", "[dof][seed]") {
  Rig& rig = seed_rig();
  const Frame linear = scene(64, 48);
  const Rendered expected = rig.render(linear);
  struct Case {
    pfx_depth_encoding encoding;
    double far_plane;
  };
  for (const Case c : {Case{PFX_DEPTH_HARDWARE, 1000}, Case{PFX_DEPTH_HARDWARE, HUGE_VAL},
                       Case{PFX_DEPTH_HARDWARE_REVERSED, 1000}, Case{PFX_DEPTH_HARDWARE_REVERSED, HUGE_VAL}}) {
    Frame f = linear;
    f.encoding = c.encoding;
    f.far_plane = c.far_plane;
    const double n = f.near_plane, far = c.far_plane;
    for (float& z : f.depth) {
      const double d = z;
      if (c.encoding == PFX_DEPTH_HARDWARE)  // window z of a standard projection
        z = static_cast<float>(std::isinf(far) ? 1.0 - n / d : (far + n - 2.0 * far * n / d) / (2.0 * (far - n)) + 0.5);
      else  // reversed, zero-to-one clip
        z = static_cast<float>(std::isinf(far) ? n / d : n * (far - d) / (d * (far - n)));
    }
    for (DepthTexture texture : {DepthTexture::R32F, DepthTexture::DEPTH_COMPONENT32F}) {
      const Rendered r = rig.render(f, texture);
      INFO("encoding " << c.encoding << " far " << far << " texture " << int(texture));
      // The decoded depths differ from the linear ones by float rounding only: < 0.001 px of CoC here.
      CHECK(max_difference(r.output, expected.output) < 0.01);
      require_matches_model(r);
    }
  }
}

TEST_CASE("seed mode autofocus focuses on the depth under the point, on the sky it focuses at infinity",
          "[dof][seed][hard]") {
  Rig& rig = seed_rig();
  rig.set("dof.focus_distance=100");
  rig.set("dof.autofocus=point");
  Frame f = scene(96, 64, 5.0);
  // The point over the in-focus strip (x from 48 to 63, top-left origin).
  rig.set("dof.focus_point=0.55,0.5");
  Rendered r = rig.render(f);
  require_matches_model(r);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t i = static_cast<size_t>(y) * f.width + x;
      if (f.depth[i] == 5.0f) REQUIRE(r.output[i * 4] == r.input.rgba[i * 4]);
    }
  // Over the sky: everything is in front of the focus, and the sky itself stays sharp.
  for (float& z : f.depth)
    if (z == 20.0f) z = HUGE_VALF;
  rig.set("dof.focus_point=0.05,0.05");
  r = rig.render(f);
  require_matches_model(r);
  const size_t corner = (static_cast<size_t>(f.height - 2) * f.width + 2) * 4;
  CHECK(r.output[corner] == r.input.rgba[corner]);
  rig.set("dof.autofocus=off");
}
