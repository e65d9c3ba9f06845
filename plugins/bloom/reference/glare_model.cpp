// PFX_REFERENCE_MODEL of the "glare" effect (see glare_effect.cpp).
#include <algorithm>
#include <cmath>

#include "bloom_levels.hpp"
#include "reference/glare_model.hpp"
#include "reference/model_common.hpp"

namespace pfx_bloom {
namespace {

using model::Plane;

// One streak pass: 16 bilinear taps b*s texels along (dx, dy), clamp-to-border, weighted.
Plane streak_pass(const Plane& src, double dx, double dy, double b, const double* weights) {
  Plane out(src.w, src.h);
  for (int y = 0; y < src.h; ++y)
    for (int x = 0; x < src.w; ++x) {
      double* o = out.at(x, y);
      for (int s = 0; s < kGlareTaps; ++s) {
        double tap[3];
        model::bilinear(src, x + 0.5 + dx * b * s, y + 0.5 + dy * b * s, model::Wrap::Border, tap);
        for (int c = 0; c < 3; ++c) o[c] += weights[s] * tap[c];
      }
    }
  return out;
}

}  // namespace

void evaluate_glare_model(const GlareSettings& g, uint32_t width, uint32_t height, const float* color, float* output,
                          ModelTrace* trace) {
  ModelTrace ignored;
  ModelTrace& t = trace ? *trace : ignored;
  t = ModelTrace{};
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  if (g.is_noop()) {  // the host copies the frame unchanged
    std::copy(color, color + static_cast<size_t>(W) * H * 4, output);
    return;
  }
  const int d = g.downscale;
  const int w = blocks_covering(W, d), h = blocks_covering(H, d), pad_x = padding_before(W, d), pad_y = padding_before(H, d);
  const double unit[3] = {1.0, 1.0, 1.0};
  const Plane bright = model::box_bright(g.bright, g.bright.measure, model::safe_frame(color, W, H, g.bright.firefly_clamp, g.bright.nonfinite),
                                         w, h, d, pad_x, pad_y, unit, kLevelSumMax);
  Plane sum(w, h);
  t.largest_stored = model::largest(bright);
  for (int j = 0; j < g.streaks; ++j) {
    double dx, dy;
    g.direction(j, &dx, &dy);
    Plane current = bright;
    for (int i = 0; i < kGlarePasses; ++i) {
      double weights[kGlareTaps];
      g.pass_weights(i, weights);
      if (i == kGlarePasses - 1)
        for (double& weight : weights) weight /= g.streaks;
      current = streak_pass(current, dx, dy, std::pow(4.0, i), weights);
      t.largest_stored = std::max(t.largest_stored, model::largest(current));
    }
    for (size_t k = 0; k < sum.rgb.size(); ++k) sum.rgb[k] += current.rgb[k];
    t.largest_stored = std::max(t.largest_stored, model::largest(sum));
  }
  t.stores = 1 + kGlarePasses + g.streaks;  // bright, two passes, the sum's n blends, the output
  model::composite(color, W, H, 1.0, g.bright.nonfinite, output, [&](int x, int y, double add[3]) {
    model::bilinear(sum, model::on_grid(x, pad_x, d), model::on_grid(y, pad_y, d), model::Wrap::Edge, add);
    for (int c = 0; c < 3; ++c) add[c] *= g.strength * g.tint[c];
  });
}

}  // namespace pfx_bloom
