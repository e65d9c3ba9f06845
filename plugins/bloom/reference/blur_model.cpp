// PFX_REFERENCE_MODEL of the Gaussian modes, gaussian and mgf (see bloom_blur_passes.cpp).
#include <algorithm>
#include <vector>

#include "bloom_levels.hpp"
#include "gaussian_taps.hpp"
#include "reference/bloom_model.hpp"
#include "reference/model_common.hpp"

namespace pfx_bloom {
namespace {

using model::bilinear;
using model::Plane;
using model::Wrap;

// One direction of the separable Gaussian into a w x h buffer: taps one output texel apart,
// bilinear reads of src with clamp-to-border, as the blur shader. scale 1: src is the same size;
// 2: src is the finer buffer (w = ceil(src.w / 2)), and output texel x reads at src's texel corner
// 2x + 1, the average of the 2x2 texels it covers.
Plane blur(const Plane& src, int w, int h, bool horizontal, double deviation, int half_taps, double scale = 1.0) {
  std::vector<double> weights(static_cast<size_t>(half_taps) + 1);
  gaussian_weights(deviation, half_taps, weights.data());
  const double step_x = horizontal ? scale : 0.0, step_y = horizontal ? 0.0 : scale;
  Plane out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double px = (x + 0.5) * scale, py = (y + 0.5) * scale;
      double* o = out.at(x, y);
      for (int k = -half_taps; k <= half_taps; ++k) {
        double tap[3];
        bilinear(src, px + k * step_x, py + k * step_y, Wrap::Border, tap);
        for (int c = 0; c < 3; ++c) o[c] += weights[static_cast<size_t>(std::abs(k))] * tap[c];
      }
    }
  return out;
}

void gain_of(const Settings& s, double gain[3]) {
  for (int c = 0; c < 3; ++c) gain[c] = s.strength * s.tint[c];
}

}  // namespace

void evaluate_gaussian_model(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output,
                             ModelTrace& trace) {
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  if (s.adds_nothing()) {
    model::composite(color, W, H, s.tone_scale, s.nonfinite, output, [](int, int, double add[3]) { add[0] = add[1] = add[2] = 0; });
    trace.stores = 1;
    return;
  }
  const LevelPlan plan = plan_for(s, width, height);
  const int w = plan.width[0], h = plan.height[0];
  double gain[3];
  gain_of(s, gain);
  const Plane bright = model::box_bright(s, model::kMeasurePerChannel, model::safe_frame(color, W, H, s.firefly_clamp, s.nonfinite),
                                         w, h, plan.block, plan.pad_x, plan.pad_y, gain, kLevelSumMax);
  const double deviation = gaussian_mode_deviation(s);
  const Plane vertical = blur(bright, w, h, false, deviation, s.half_taps);
  const Plane bloom = blur(vertical, w, h, true, deviation, s.half_taps);
  trace.largest_stored = std::max({model::largest(bright), model::largest(vertical), model::largest(bloom)});
  trace.stores = 4;  // bright, vertical, horizontal, output
  model::composite(color, W, H, s.tone_scale, s.nonfinite, output, [&](int x, int y, double add[3]) {
    bilinear(bloom, model::on_grid(x, plan.pad_x, plan.block), model::on_grid(y, plan.pad_y, plan.block), Wrap::Edge,
             add);
  });
}

void evaluate_mgf_model(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output,
                        ModelTrace& trace) {
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  const LevelPlan plan = plan_for(s, width, height);
  double gain[3], weights[kMaxLevels];
  gain_of(s, gain);
  level_weights(s, plan.count, weights);
  std::vector<Plane> gauss;
  gauss.reserve(plan.count);
  Plane source = model::box_bright(s, s.measure, model::safe_frame(color, W, H, s.firefly_clamp, s.nonfinite), plan.width[0],
                                   plan.height[0], plan.block, plan.pad_x, plan.pad_y, gain, kLevelSumMax, s.karis);
  for (int i = 0; i < plan.count; ++i) {
    const Plane& from = i == 0 ? source : gauss[i - 1];
    const Plane across = blur(from, plan.width[i], plan.height[i], true, kMgfDeviation, kMgfTaps / 2, i == 0 ? 1.0 : 2.0);
    gauss.push_back(blur(across, plan.width[i], plan.height[i], false, kMgfDeviation, kMgfTaps / 2));
    trace.largest_stored = std::max({trace.largest_stored, model::largest(from), model::largest(across),
                                     model::largest(gauss.back())});
  }
  trace.stores = 2 * plan.count + 2;  // bright, two blurs per buffer, output
  model::composite(color, W, H, 1.0, s.nonfinite, output, [&](int x, int y, double add[3]) {
    add[0] = add[1] = add[2] = 0;
    for (int i = 0; i < plan.count; ++i) {
      double tap[3];
      const int scale = plan.block << i;
      bilinear(gauss[i], model::on_grid(x, plan.pad_x, scale), model::on_grid(y, plan.pad_y, scale), Wrap::Edge, tap);
      for (int c = 0; c < 3; ++c) add[c] += weights[i] * tap[c];
    }
  });
}

}  // namespace pfx_bloom
