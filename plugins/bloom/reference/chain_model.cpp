// PFX_REFERENCE_MODEL of the pyramid modes, chain and chain13 (see bloom_chain_passes.cpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "bloom_levels.hpp"
#include "reference/bloom_model.hpp"
#include "reference/model_common.hpp"

namespace pfx_bloom {
namespace {

using model::bilinear;
using model::Plane;
using model::Wrap;

// The bright part of the bilinear tap (dx, dy) texels off (px, py) in the frame.
void bright_tap(const Settings& s, const Plane& frame, double px, double py, double dx, double dy, double out[3]) {
  bilinear(frame, px + dx, py + dy, Wrap::Border, out);
  model::bright_part(s, s.measure, out);
}

// The pyramid's five taps: the centre weighted 4, the four diagonal neighbours 1, / 8. With karis each
// weight is multiplied by the tap's Karis weight and the sum divided by the weights' sum.
void bright5(const Settings& s, const Plane& frame, double px, double py, double out[3]) {
  const struct {
    int dx, dy;
    double weight;
  } taps[5] = {{0, 0, 4.0}, {-1, 1, 1.0}, {1, 1, 1.0}, {-1, -1, 1.0}, {1, -1, 1.0}};
  double weights = 0;
  out[0] = out[1] = out[2] = 0.0;
  for (const auto& t : taps) {
    double tap[3];
    bright_tap(s, frame, px, py, t.dx, t.dy, tap);
    const double weight = t.weight * (s.karis ? model::karis_weight(tap) : 1.0);
    for (int c = 0; c < 3; ++c) out[c] += weight * tap[c];
    weights += weight;
  }
  for (int c = 0; c < 3; ++c) out[c] /= weights;
}

// The Karis average of four taps: each weighted 1 / (1 + Rec. 709 luma).
void karis(const double* const taps[4], double out[3]) {
  double weight_sum = 0;
  out[0] = out[1] = out[2] = 0;
  for (int t = 0; t < 4; ++t) {
    const double w = model::karis_weight(taps[t]);
    weight_sum += w;
    for (int c = 0; c < 3; ++c) out[c] += w * taps[t][c];
  }
  for (int c = 0; c < 3; ++c) out[c] /= weight_sum;
}

// Jimenez's 13 taps as five boxes of four: the centre box (taps at +-1) 0.5, the corner boxes
// (taps at 0 and +-2) 0.125 each, every box a Karis average of its taps' bright parts.
void bright13(const Settings& s, const Plane& frame, double px, double py, double out[3]) {
  double p[5][5][3];  // p[dy + 2][dx + 2]
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      if ((dx + dy) % 2 == 0) bright_tap(s, frame, px, py, dx, dy, p[dy + 2][dx + 2]);
  const double* centre_taps[4] = {p[1][1], p[1][3], p[3][1], p[3][3]};
  double centre[3], box[3];
  karis(centre_taps, centre);
  for (int c = 0; c < 3; ++c) out[c] = 0.5 * centre[c];
  for (int oy : {0, 2})
    for (int ox : {0, 2}) {
      const double* corner_taps[4] = {p[oy][ox], p[oy][ox + 2], p[oy + 2][ox], p[oy + 2][ox + 2]};
      karis(corner_taps, box);
      for (int c = 0; c < 3; ++c) out[c] += 0.125 * box[c];
    }
}

Plane bright_pass(const Settings& s, const Plane& frame, int w, int h, int level_count) {
  Plane out(w, h);
  const double per_level = s.strength / level_count, cap = kLevelSumMax / level_count;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double px = model::centre_x(x, w, frame), py = model::centre_y(y, h, frame);
      double sum[3];
      if (s.mode == MODE_CHAIN13)
        bright13(s, frame, px, py, sum);
      else
        bright5(s, frame, px, py, sum);
      for (int c = 0; c < 3; ++c) out.at(x, y)[c] = std::min(sum[c] * per_level * s.tint[c], cap);
    }
  return out;
}

// One downsample tap set: offsets (texels of the source) and weights.
struct Tap {
  double dx, dy, weight;
};

std::vector<Tap> down_taps(int mode) {
  std::vector<Tap> taps;
  if (mode == MODE_CHAIN13) {
    // Per tap, the weights of the boxes it belongs to, summed: 0.125 for the inner four and the
    // centre, 0.0625 for the edge middles, 0.03125 for the outer corners.
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        if ((dx + dy) % 2 != 0) continue;
        const bool inner = std::abs(dx) == 1 || (dx == 0 && dy == 0);
        const int twos = (std::abs(dx) == 2) + (std::abs(dy) == 2);
        taps.push_back({double(dx), double(dy), inner ? 0.125 : twos == 1 ? 0.0625 : 0.03125});
      }
    return taps;
  }
  static const double kOffsets[4] = {-2.75, -0.92, 0.92, 2.75};
  static const double kWeights[4] = {0.1087, 0.3913, 0.3913, 0.1087};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) taps.push_back({kOffsets[i], kOffsets[j], kWeights[i] * kWeights[j]});
  return taps;
}

Plane downsample(const Plane& src, int w, int h, const std::vector<Tap>& taps) {
  Plane out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double px = model::centre_x(x, w, src), py = model::centre_y(y, h, src);
      double* o = out.at(x, y);
      for (const Tap& t : taps) {
        double tap[3];
        bilinear(src, px + t.dx, py + t.dy, Wrap::Border, tap);
        for (int c = 0; c < 3; ++c) o[c] += tap[c] * t.weight;
      }
    }
  return out;
}

// The 3x3 tent of src at the centre of pixel (x, y) of a w x h image: four taps half a source
// texel off the centre, clamp-to-edge.
void tent(const Plane& src, int x, int y, int w, int h, double out[3]) {
  const double px = model::centre_x(x, w, src), py = model::centre_y(y, h, src);
  out[0] = out[1] = out[2] = 0.0;
  for (const auto& d : {std::pair{-0.5, 0.5}, std::pair{0.5, 0.5}, std::pair{0.5, -0.5}, std::pair{-0.5, -0.5}}) {
    double tap[3];
    bilinear(src, px + d.first, py + d.second, Wrap::Edge, tap);
    for (int c = 0; c < 3; ++c) out[c] += 0.25 * tap[c];
  }
}

}  // namespace

void evaluate_chain_model(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output,
                          ModelTrace& trace) {
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  const LevelPlan plan = plan_for(s, width, height);
  const std::vector<Tap> taps = down_taps(s.mode);
  std::vector<Plane> levels;
  levels.reserve(plan.count);
  levels.push_back(bright_pass(s, model::safe_frame(color, W, H, s.firefly_clamp, s.nonfinite), plan.width[0], plan.height[0], plan.count));
  for (int i = 1; i < plan.count; ++i) levels.push_back(downsample(levels[i - 1], plan.width[i], plan.height[i], taps));
  for (const Plane& level : levels) trace.largest_stored = std::max(trace.largest_stored, model::largest(level));
  for (int i = plan.count - 2; i >= 0; --i) {
    Plane& dst = levels[i];
    for (int y = 0; y < dst.h; ++y)
      for (int x = 0; x < dst.w; ++x) {
        double add[3];
        tent(levels[i + 1], x, y, dst.w, dst.h, add);
        for (int c = 0; c < 3; ++c) dst.at(x, y)[c] += add[c];
      }
    trace.largest_stored = std::max(trace.largest_stored, model::largest(dst));
  }
  // bright, L - 1 downsamples, L - 1 blended upsamples, the output.
  trace.stores = 2 * plan.count;
  model::composite(color, W, H, 1.0, s.nonfinite, output, [&](int x, int y, double add[3]) { tent(levels[0], x, y, W, H, add); });
}

}  // namespace pfx_bloom
