// The "gather" mode on the GPU against its CPU model (PFX_REFERENCE_MODEL), the bit-exact skip of
// in-focus tiles, and the properties the mode is for: no halo of a sharp object over a blurred
// background (which the 16-tap disk mode has), no blurred background over a sharp edge, a blurred foreground
// spreading over the sharp background behind it (which the disk mode does not), and energy kept.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "dof_rig.hpp"

using namespace dof_test;

namespace {

Rig& gather_rig(const char* resolution, int samples = 32) {
  Rig& rig = shared_rig("gather");
  rig.set(std::string("dof.resolution=") + resolution);
  rig.set("dof.samples=" + std::to_string(samples));
  return rig;
}

struct Comparison {
  double worst = 0;     // largest |gpu - model| / tolerance
  double fraction = 0;  // of values over the tolerance
};

// |gpu - model| <= 2^-8 S + 2^-9 |model| + 1e-5, S the largest safe input magnitude within the
// gather's reach. The GPU computes in float what the model does in double, from the same half-float
// intermediates; its sums of up to 256 weighted samples and the half-float stores of the blur and
// the output stay within this. A CoC computed in float can round to the neighbouring half float, and
// a sample exactly at the pixel's CoC can then fall in the other field: a few isolated values may
// differ by more, so the test bounds their share, not their existence.
Comparison compare(const Rendered& r) {
  const int w = r.input.width, h = r.input.height, reach = 20;
  Comparison c;
  size_t over = 0, count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double big = 0;
      for (int v = std::max(0, y - reach); v <= std::min(h - 1, y + reach); v += 1)
        for (int u = std::max(0, x - reach); u <= std::min(w - 1, x + reach); u += 1)
          for (int k = 0; k < 3; ++k) {
            const double value = r.input.at(u, v)[k];
            big = std::max(big, std::isnan(value) ? 0.0 : std::min(std::fabs(value), 65504.0));
          }
      for (int k = 0; k < 3; ++k) {
        const size_t i = (static_cast<size_t>(y) * w + x) * 4 + k;
        const double m = r.model[i], o = r.output[i];
        const double tolerance = std::ldexp(big, -8) + std::ldexp(std::fabs(m), -9) + 1e-5;
        const double ratio = std::isfinite(o) ? std::fabs(o - m) / tolerance : HUGE_VAL;
        c.worst = std::max(c.worst, ratio);
        over += ratio > 1.0;
        ++count;
      }
    }
  c.fraction = double(over) / double(count);
  return c;
}

void require_matches_model(const Rendered& r) {
  const Comparison c = compare(r);
  INFO(r.input.width << "x" << r.input.height << ": worst error / tolerance " << c.worst << ", over it "
                     << c.fraction * 100 << "%");
  if (std::getenv("DOF_TEST_VERBOSE"))
    std::fprintf(stderr, "%dx%d worst %.4f over %.4f%%\n", r.input.width, r.input.height, c.worst, c.fraction * 100);
  REQUIRE(c.fraction <= 0.001);
}

}  // namespace

TEST_CASE("gather mode matches its CPU model at half and full resolution, 16 to 128 samples", "[dof][gather]") {
  for (const char* resolution : {"half", "full"})
    for (int samples : {16, 32, 128})
      for (const auto& size : {std::pair{96, 64}, std::pair{37, 23}}) {
        Rig& rig = gather_rig(resolution, samples);
        INFO(resolution << " " << samples << " samples");
        const Rendered r = rig.render(scene(size.first, size.second));
        CHECK(r.passes == (std::string(resolution) == "half" ? 6u : 5u));
        require_matches_model(r);
      }
}

TEST_CASE("the gather-mode model comparison catches a 10% f-number error", "[dof][gather]") {
  for (const char* resolution : {"half", "full"}) {
    Rig& rig = gather_rig(resolution);
    Rendered r = rig.render(scene(96, 64));
    rig.set("dof.f_number=0.11");
    r.model = reference(rig, r.input, PFX_REFERENCE_MODEL);
    INFO(resolution);
    CHECK(compare(r).fraction > 0.05);
  }
}

namespace {

// 64x48 (4x3 tiles): colours of every sign and size that half floats hold exactly, depth at the
// focus distance everywhere except in `blurred_tiles` whole tiles at 30 m.
Frame tiled_frame(int blurred_tiles) {
  Frame f(64, 48);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      float* c = f.at(x, y);
      c[0] = float((x * 37 + y * 11) % 97) / 8.0f - 4.0f;
      c[1] = (x + y) % 5 == 0 ? 60000.0f : float(x) / 64.0f;
      c[2] = float(y % 7) * 0.125f;
      c[3] = float(x % 3) * 0.5f;
      f.z(x, y) = (x / 16 + 4 * (y / 16) < blurred_tiles) ? 30.0f : 5.0f;
    }
  return f;
}

}  // namespace

TEST_CASE("gather mode reproduces in-focus tiles bit for bit, whole frame or next to blurred tiles",
          "[dof][gather]") {
  for (const char* resolution : {"half", "full"}) {
    Rig& rig = gather_rig(resolution);
    // Far blur (30 m behind a 5 m focus) cannot reach into other tiles; a near blur would.
    for (int blurred : {0, 1, 5}) {
      const Frame f = tiled_frame(blurred);
      const Rendered r = rig.render(f);
      size_t exact = 0, changed = 0;
      for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
          const size_t i = (static_cast<size_t>(y) * f.width + x) * 4;
          const bool in_focus_tile = f.depth[i / 4] == 5.0f;
          for (int k = 0; k < 4; ++k) {
            if (in_focus_tile) {
              INFO(resolution << ", " << blurred << " blurred tiles, pixel " << x << "," << y);
              REQUIRE(r.output[i + k] == r.input.rgba[i + k]);
              ++exact;
            } else {
              changed += r.output[i + k] != r.input.rgba[i + k];
            }
          }
        }
      CHECK(exact == static_cast<size_t>(64 * 48 - 256 * blurred) * 4);
      if (blurred) CHECK(changed > 0);
    }
  }
}

namespace {

// A 96x64 frame: a square at the focus distance in front of a backdrop at 60 m (far blur).
Frame square_over_backdrop(float square, float backdrop, float square_depth = 5.0f) {
  Frame f(96, 64);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const bool inside = x >= 32 && x < 64 && y >= 16 && y < 48;
      float* c = f.at(x, y);
      c[0] = c[1] = c[2] = inside ? square : backdrop;
      f.z(x, y) = inside ? square_depth : 60.0f;
    }
  return f;
}

// Largest value in the backdrop within `band` pixels outside the square.
double brightest_outside(const Rendered& r, int band) {
  double m = 0;
  for (int y = 16 - band; y < 48 + band; ++y)
    for (int x = 32 - band; x < 64 + band; ++x) {
      const bool inside = x >= 32 && x < 64 && y >= 16 && y < 48;
      if (!inside) m = std::max(m, double(r.output[(static_cast<size_t>(y) * 96 + x) * 4]));
    }
  return m;
}

}  // namespace

TEST_CASE("gather mode: a sharp object does not halo into the blurred background behind it (the disk mode does)",
          "[dof][gather]") {
  const Frame f = square_over_backdrop(1.0f, 0.0625f);
  for (const char* resolution : {"half", "full"}) {
    Rig& rig = gather_rig(resolution, 64);
    const Rendered r = rig.render(f);
    INFO(resolution);
    CHECK(brightest_outside(r, 6) < 0.0625 + 0.002);
  }
  Rig& rig = gather_rig("half");
  rig.set("dof.mode=seed");
  const Rendered seed = rig.render(f);
  CHECK(brightest_outside(seed, 6) > 0.2);
}

TEST_CASE("gather mode: a blurred background does not bleed over a sharp edge in front of it", "[dof][gather]") {
  const Frame f = square_over_backdrop(0.0625f, 1.0f);
  for (const char* resolution : {"half", "full"}) {
    Rig& rig = gather_rig(resolution, 64);
    const Rendered r = rig.render(f);
    double worst = 0;
    for (int y = 16; y < 48; ++y)
      for (int x = 32; x < 64; ++x)
        worst = std::max(worst, std::fabs(r.output[(static_cast<size_t>(y) * 96 + x) * 4] - 0.0625));
    INFO(resolution);
    CHECK(worst < 1e-3);
  }
}

TEST_CASE("gather mode: a blurred foreground spreads over the sharp background behind it", "[dof][gather]") {
  // The square at 1 m in front of a 5 m focus: a CoC of about -8.5 px; the backdrop in focus.
  Frame f = square_over_backdrop(1.0f, 0.0f, 1.0f);
  for (float& z : f.depth)
    if (z == 60.0f) z = 5.0f;
  for (const char* resolution : {"half", "full"}) {
    Rig& rig = gather_rig(resolution, 64);
    const Rendered r = rig.render(f);
    INFO(resolution);
    // Just outside the left edge the square covers part of the lens; farther out it covers none.
    const double at_edge = r.output[(static_cast<size_t>(32) * 96 + 31) * 4];
    const double beyond = r.output[(static_cast<size_t>(32) * 96 + 20) * 4];
    CHECK(at_edge > 0.2);
    CHECK(at_edge < 0.8);
    CHECK(beyond < 0.01);
  }
  // The disk mode leaves the sharp background sharp: the foreground's blur ends at its own edge.
  Rig& rig = gather_rig("half");
  rig.set("dof.mode=seed");
  CHECK(rig.render(f).output[(static_cast<size_t>(32) * 96 + 31) * 4] == 0.0f);
}

TEST_CASE("gather mode keeps the energy of a bright point in a blurred backdrop", "[dof][gather]") {
  Frame f(96, 64);
  for (float& z : f.depth) z = 60.0f;
  for (size_t i = 0; i < f.rgba.size(); i += 4) f.rgba[i] = f.rgba[i + 1] = f.rgba[i + 2] = 0.25f;
  f.at(48, 32)[0] = 1000.0f;
  for (const char* resolution : {"half", "full"})
    for (int samples : {32, 128}) {
      Rig& rig = gather_rig(resolution, samples);
      const Rendered r = rig.render(f);
      double added = 0;
      for (size_t i = 0; i < r.output.size(); i += 4) added += r.output[i] - 0.25;
      INFO(resolution << " " << samples << " samples: energy " << added << " of 999.75");
      CHECK(added == Approx(999.75).epsilon(0.1));
    }
}
