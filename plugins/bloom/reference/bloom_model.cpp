#include "bloom_model.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bloom_levels.hpp"

namespace pfx_bloom {
namespace {

enum class Wrap { Border, Edge };

// An RGB image of doubles, rows bottom first.
struct Plane {
  int w = 0, h = 0;
  std::vector<double> rgb;
  Plane(int width, int height) : w(width), h(height), rgb(static_cast<size_t>(width) * height * 3, 0.0) {}
  double* at(int x, int y) { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
  const double* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
};

// The texel (x, y) under a wrap mode: clamp-to-border reads transparent black outside.
void texel(const Plane& p, int x, int y, Wrap wrap, double out[3]) {
  if (wrap == Wrap::Border && (x < 0 || y < 0 || x >= p.w || y >= p.h)) {
    out[0] = out[1] = out[2] = 0.0;
    return;
  }
  const double* t = p.at(std::clamp(x, 0, p.w - 1), std::clamp(y, 0, p.h - 1));
  out[0] = t[0], out[1] = t[1], out[2] = t[2];
}

// GL_LINEAR at (px, py) in texels, texel centres at +0.5 (GL 4.5 §8.14.2), exact weights.
void bilinear(const Plane& p, double px, double py, Wrap wrap, double out[3]) {
  const double u = px - 0.5, v = py - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const double a = u - fu, b = v - fv;
  const int i = static_cast<int>(fu), j = static_cast<int>(fv);
  double t00[3], t10[3], t01[3], t11[3];
  texel(p, i, j, wrap, t00);
  texel(p, i + 1, j, wrap, t10);
  texel(p, i, j + 1, wrap, t01);
  texel(p, i + 1, j + 1, wrap, t11);
  for (int c = 0; c < 3; ++c)
    out[c] = (1 - b) * ((1 - a) * t00[c] + a * t10[c]) + b * ((1 - a) * t01[c] + a * t11[c]);
}

bool is_nan(float v) { return std::isnan(v); }

// What the bright pass reads from the frame: NaN -> 0, negative -> 0, at most the clamp (+Inf too).
Plane safe_frame(const float* color, int w, int h, double clamp_to) {
  Plane p(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = color[(static_cast<size_t>(y) * w + x) * 4 + c];
        p.at(x, y)[c] = is_nan(v) ? 0.0 : std::clamp(static_cast<double>(v), 0.0, clamp_to);
      }
  return p;
}

void bright_part(const Settings& s, double c[3]) {
  const double b = s.measure == MEASURE_LUMINANCE ? 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
                                                  : std::max(c[0], std::max(c[1], c[2]));
  double part = std::max(b - s.threshold, 0.0);
  if (s.knee > 0) {
    const double soft = std::clamp(b - s.threshold + s.knee, 0.0, 2.0 * s.knee);
    part = std::max(part, soft * soft / (4.0 * s.knee));
  }
  const double ratio = part / std::max(b, kBrightnessFloor);
  for (int i = 0; i < 3; ++i) c[i] *= ratio;
}

Plane bright_pass(const Settings& s, const Plane& frame, int w, int h, int level_count) {
  Plane out(w, h);
  const double per_level = s.strength / level_count, cap = kLevelSumMax / level_count;
  const double corners[4][2] = {{-1, 1}, {1, 1}, {-1, -1}, {1, -1}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double px = (x + 0.5) / w * frame.w, py = (y + 0.5) / h * frame.h;
      double sum[3], tap[3];
      bilinear(frame, px, py, Wrap::Border, tap);
      bright_part(s, tap);
      for (int c = 0; c < 3; ++c) sum[c] = 4.0 * tap[c];
      for (const auto& d : corners) {
        bilinear(frame, px + d[0], py + d[1], Wrap::Border, tap);
        bright_part(s, tap);
        for (int c = 0; c < 3; ++c) sum[c] += tap[c];
      }
      for (int c = 0; c < 3; ++c) out.at(x, y)[c] = std::min(sum[c] / 8.0 * per_level * s.tint[c], cap);
    }
  return out;
}

Plane downsample(const Plane& src, int w, int h) {
  static const double kOffsets[4] = {-2.75, -0.92, 0.92, 2.75};
  static const double kWeights[4] = {0.1087, 0.3913, 0.3913, 0.1087};
  Plane out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double px = (x + 0.5) / w * src.w, py = (y + 0.5) / h * src.h;
      double* o = out.at(x, y);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          double tap[3];
          bilinear(src, px + kOffsets[i], py + kOffsets[j], Wrap::Border, tap);
          for (int c = 0; c < 3; ++c) o[c] += tap[c] * kWeights[i] * kWeights[j];
        }
    }
  return out;
}

// The 3x3 tent of src at the centre of pixel (x, y) of a w x h image: four taps half a source
// texel off the centre, clamp-to-edge.
void tent(const Plane& src, int x, int y, int w, int h, double out[3]) {
  const double px = (x + 0.5) / w * src.w, py = (y + 0.5) / h * src.h;
  const double corners[4][2] = {{-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}};
  out[0] = out[1] = out[2] = 0.0;
  for (const auto& d : corners) {
    double tap[3];
    bilinear(src, px + d[0], py + d[1], Wrap::Edge, tap);
    for (int c = 0; c < 3; ++c) out[c] += 0.25 * tap[c];
  }
}

double finite_signed(float v) { return is_nan(v) ? 0.0 : std::clamp(static_cast<double>(v), -kHalfMax, kHalfMax); }

}  // namespace

void evaluate_chain_model(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output) {
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  const size_t pixels = static_cast<size_t>(W) * H;
  if (s.is_noop()) {  // the host copies the frame unchanged
    std::copy(color, color + pixels * 4, output);
    return;
  }
  const LevelPlan plan = plan_levels(width, height, s.levels, s.auto_min_size);
  std::vector<Plane> levels;
  levels.reserve(plan.count);
  levels.push_back(bright_pass(s, safe_frame(color, W, H, s.firefly_clamp), plan.width[0], plan.height[0], plan.count));
  for (int i = 1; i < plan.count; ++i) levels.push_back(downsample(levels[i - 1], plan.width[i], plan.height[i]));
  for (int i = plan.count - 2; i >= 0; --i) {
    Plane& dst = levels[i];
    for (int y = 0; y < dst.h; ++y)
      for (int x = 0; x < dst.w; ++x) {
        double add[3];
        tent(levels[i + 1], x, y, dst.w, dst.h, add);
        for (int c = 0; c < 3; ++c) dst.at(x, y)[c] += add[c];
      }
  }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t k = (static_cast<size_t>(y) * W + x) * 4;
      double bloom[3];
      tent(levels[0], x, y, W, H, bloom);
      for (int c = 0; c < 3; ++c)
        output[k + c] = static_cast<float>(std::min(finite_signed(color[k + c]) + bloom[c], kHalfMax));
      output[k + 3] = static_cast<float>(finite_signed(color[k + 3]));
    }
}

}  // namespace pfx_bloom
