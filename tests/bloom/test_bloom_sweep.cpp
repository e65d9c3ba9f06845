// No row or column of the frame is lost: a one-pixel light swept over every row and every column of
// odd-sized frames adds bloom wherever it is, in the amount a full-resolution version of the same
// kernel keeps inside the frame. The downscaled buffers of gaussian, mgf and glare average blocks
// of d x d pixels; rounded down, `size mod d` rows and columns were never read and a light there
// added nothing at all (a one-pixel light moving across the frame blinked).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bloom_levels.hpp"  // plan_for: the level count the ideal uses
#include "bloom_rig.hpp"
#include "glare_params.hpp"
#include "reference/psf.hpp"

using namespace bloom_test;

namespace {

constexpr float kLight = 1000.0f;  // exact in half; with threshold 0 all of it blooms

// Sums of a kernel over rectangles of taps, in O(1) each.
class KernelWindow {
 public:
  explicit KernelWindow(const pfx_bloom::fft::Kernel& k) : k_(k), sums_(size_t(k.w + 1) * (k.h + 1), 0.0) {
    for (int y = 0; y < k.h; ++y)
      for (int x = 0; x < k.w; ++x)
        sums_[index(x + 1, y + 1)] = k.at(x, y) + sums_[index(x, y + 1)] + sums_[index(x + 1, y)] - sums_[index(x, y)];
  }
  // The share of a light at (px, py) that the kernel puts inside a w x h frame; between pixels,
  // interpolated.
  double kept(double px, double py, int w, int h) const {
    const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
    const double fx = px - x, fy = py - y;
    return (1 - fy) * ((1 - fx) * kept_at(x, y, w, h) + fx * kept_at(x + 1, y, w, h)) +
           fy * ((1 - fx) * kept_at(x, y + 1, w, h) + fx * kept_at(x + 1, y + 1, w, h));
  }

 private:
  double kept_at(int px, int py, int w, int h) const {
    const int x0 = std::clamp(k_.cx - px, 0, k_.w), x1 = std::clamp(k_.cx + w - px, 0, k_.w);
    const int y0 = std::clamp(k_.cy - py, 0, k_.h), y1 = std::clamp(k_.cy + h - py, 0, k_.h);
    return sums_[index(x1, y1)] - sums_[index(x0, y1)] - sums_[index(x1, y0)] + sums_[index(x0, y0)];
  }
  size_t index(int x, int y) const { return size_t(y) * (k_.w + 1) + x; }
  pfx_bloom::fft::Kernel k_;
  std::vector<double> sums_;
};

// glare's streaks from Kawase's streak formula (as test_glare.cpp): streak j's tap t = s0 + 4 s1 + 16 s2
// lies d * t texels of the frame... along -direction j, weighted w0(s0) w1(s1) w2(s2) / streaks, at
// full resolution of a buffer d times coarser. The share of a light at (px, py) whose taps land
// inside the frame (a tap's centre within half a pixel of it).
double glare_kept(const pfx_bloom::GlareSettings& g, double px, double py, int w, int h) {
  double weights[pfx_bloom::kGlarePasses][pfx_bloom::kGlareTaps];
  for (int i = 0; i < pfx_bloom::kGlarePasses; ++i) g.pass_weights(i, weights[i]);
  double kept = 0;
  for (int j = 0; j < g.streaks; ++j) {
    double dx, dy;
    g.direction(j, &dx, &dy);
    for (int s0 = 0; s0 < 16; ++s0)
      for (int s1 = 0; s1 < 16; ++s1)
        for (int s2 = 0; s2 < 16; ++s2) {
          const double t = g.downscale * (s0 + 4.0 * s1 + 16.0 * s2);
          const double x = px - t * dx, y = py - t * dy;
          if (x >= -0.5 && y >= -0.5 && x < w - 0.5 && y < h - 0.5)
            kept += weights[0][s0] * weights[1][s1] * weights[2][s2] / g.streaks;
        }
  }
  return kept;
}

// The bloom a variant adds to a light at (px, py), as a share of the light.
double added_share(Rig& rig, int w, int h, int px, int py) {
  Picture input(w, h, 0, 0, 0);
  float* c = input.at(px, py);
  c[0] = c[1] = c[2] = kLight;
  const Picture out = rig.render_output(input);
  double sum = 0;
  for (size_t i = 0; i < out.rgba.size(); ++i)
    if (i % 4 != 3) sum += double(out.rgba[i]) - input.rgba[i];
  return sum / (3.0 * kLight);
}

// Every position on small sides; on long ones the first and last 12 (every partial block at a
// downscale up to 8, at both ends, since the frame sits centred on its blocks, and the full block
// beside it) and a run of 12 in the middle.
std::vector<int> positions(int side) {
  std::vector<int> p;
  for (int i = 0; i < side; ++i)
    if (side <= 64 || i < 12 || i >= side - 12 || std::abs(i - side / 2) < 6) p.push_back(i);
  return p;
}

// The centre of the block of `block` pixels that holds pixel p, on a side of `side` pixels centred on
// ceil(side / block) blocks (the smaller half of the padding first; docs/effects/bloom.md): where a
// downscaled buffer puts the pixel's light (kept inside the frame when the block hangs over its edge).
double block_centre(int p, int side, int block) {
  const int pad = ((side + block - 1) / block * block - side) / 2;
  const double centre = (p + pad) / block * block - pad + (block - 1) / 2.0;
  return std::clamp(centre, 0.0, side - 1.0);
}

struct Variant {
  const char* effect;
  const char* settings[2];
  int downscale;  // the block the buffer averages (mgf: 4)
};

// The bound. A downscaled buffer moves a pixel's light to the centre of its block, so the bloom it
// adds is compared with what the full-resolution kernel (the mode's ideal PSF; glare's streaks from
// Kawase's streak formula) keeps inside the frame for a light there: the ratio then only follows the
// mode's own border handling (clamp-to-edge upsampling, mgf's cascade of buffers that each lose
// light at the border — about half of its ideal's at the edge, also at sizes that are multiples of
// 4 — and glare's taps leaving the frame), which changes slowly: measured at most 0.07 between
// neighbouring pixels for gaussian and 0.19 for mgf and glare on these frames. One more effect is
// the padding's: a block hanging r < d pixels into the frame gives its light to those r pixels only,
// which where the kernel is narrower than a block (glare on 3x2: its streaks leave the frame at
// once) keeps r / d of it, never less than half since the smaller half of the padding goes first.
// A row or column that no block reads adds nothing (a step of 1) and one read by two blocks twice
// the light (a step of 0.5), so every step must stay below 0.5. And no light may be lost beyond
// what those two effects explain: the border handling keeps at least about half of the kernel's
// light at the edge and the padding at least half of what is left, so the ratio stays above a
// quarter; a pixel read twice would reach 2. Measured here: 0.386 (glare at quarter resolution on
// 3x2) to 1.325 (gaussian, downscale 8, on 3x2).
void sweep(const Variant& v, int w, int h) {
  Rig rig(v.effect);
  rig.set("threshold=0");
  for (const char* s : v.settings) rig.set(s);
  const bool glare = std::string(v.effect) == "glare";
  pfx_bloom::fft::Kernel kernel{1, 1, 0, 0, {1.0}};
  if (!glare) {
    const pfx_bloom::Settings s = pfx_bloom::settings_from(rig.values());
    kernel = pfx_bloom::psf::of_mode(s, pfx_bloom::plan_for(s, w, h).count, w, h);
  }
  const KernelWindow window(kernel);
  const pfx_bloom::GlareSettings g = pfx_bloom::glare_settings_from(rig.values());
  double lowest = HUGE_VAL, highest = 0, step = 0, previous = -1;
  int last_x = -9, last_y = -9;
  std::string worst_step;
  auto visit = [&](int x, int y) {
    const double gpu = added_share(rig, w, h, x, y);
    INFO(v.effect << " " << v.settings[0] << " " << v.settings[1] << " " << w << "x" << h << ": light at (" << x << ", "
                  << y << ") adds " << gpu);
    REQUIRE(gpu > 0.0);
    const double cx = block_centre(x, w, v.downscale), cy = block_centre(y, h, v.downscale);
    const double ratio = gpu / (glare ? glare_kept(g, cx, cy, w, h) : window.kept(cx, cy, w, h));
    lowest = std::min(lowest, ratio);
    highest = std::max(highest, ratio);
    if (std::abs(x - last_x) + std::abs(y - last_y) == 1) {
      const double change = std::fabs(ratio - previous) / std::max(ratio, previous);
      if (change > step) worst_step = "(" + std::to_string(last_x) + ", " + std::to_string(last_y) + ") to (" +
                                      std::to_string(x) + ", " + std::to_string(y) + ")";
      step = std::max(step, change);
    }
    previous = ratio, last_x = x, last_y = y;
  };
  for (int x : positions(w)) visit(x, h / 2);
  for (int y : positions(h)) visit(w / 2, y);
  if (std::getenv("BLOOM_TEST_VERBOSE"))
    std::fprintf(stderr, "sweep %s %s %s %dx%d: added / kept %.4f .. %.4f, largest step %.4f %s\n", v.effect,
                 v.settings[0], v.settings[1], w, h, lowest, highest, step, worst_step.c_str());
  INFO(v.effect << " " << v.settings[0] << " " << v.settings[1] << " " << w << "x" << h << ": added / kept " << lowest
                << " .. " << highest << ", largest step " << step << " from " << worst_step);
  CHECK(step < 0.5);
  CHECK(lowest > 0.25);
  CHECK(highest < 2.0);
}

// Every downscaled variant: gaussian at even and odd downscales, mgf (blocks of 4, then its
// cascade), glare at half and quarter resolution.
const Variant kDownscaled[] = {{"bloom", {"mode=gaussian", "downscale=2"}, 2}, {"bloom", {"mode=gaussian", "downscale=3"}, 3},
                             {"bloom", {"mode=gaussian", "downscale=4"}, 4}, {"bloom", {"mode=gaussian", "downscale=8"}, 8},
                             {"bloom", {"mode=mgf", "levels=0"}, 4},         {"glare", {"resolution=half", "streaks=4"}, 2},
                             {"glare", {"resolution=quarter", "streaks=4"}, 4}};

}  // namespace

TEST_CASE("a one-pixel light on every row and column of 64x19 and 3x2 keeps its bloom", "[bloom][sweep]") {
  for (const Variant& v : kDownscaled) {
    sweep(v, 64, 19);
    sweep(v, 3, 2);
  }
}

TEST_CASE("a one-pixel light over 1023x577 keeps its bloom, in the last size mod d rows and columns too", "[bloom][sweep]") {
  for (const Variant& v : kDownscaled) sweep(v, 1023, 577);
}
