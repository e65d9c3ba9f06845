#include "reference/ideal.hpp"

#include <algorithm>
#include <vector>

#include "bloom_levels.hpp"
#include "reference/model_common.hpp"
#include "reference/psf.hpp"

namespace pfx_bloom {

void evaluate_ideal(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output) {
  const int W = static_cast<int>(width), H = static_cast<int>(height);
  const size_t pixels = static_cast<size_t>(W) * H;
  if (s.is_noop()) {
    std::copy(color, color + pixels * 4, output);
    return;
  }
  const double frame_scale = s.mode == MODE_GAUSSIAN ? s.tone_scale : 1.0;
  if (s.adds_nothing()) {
    model::composite(color, W, H, frame_scale, s.nonfinite, output, [](int, int, double add[3]) { add[0] = add[1] = add[2] = 0; });
    return;
  }
  const int measure = s.mode == MODE_GAUSSIAN ? model::kMeasurePerChannel : s.measure;
  const model::Plane frame = model::safe_frame(color, W, H, s.firefly_clamp, s.nonfinite);
  std::vector<double> planes[3];
  for (auto& p : planes) p.resize(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    double c[3] = {frame.rgb[i * 3], frame.rgb[i * 3 + 1], frame.rgb[i * 3 + 2]};
    model::bright_part(s, measure, c);
    for (int k = 0; k < 3; ++k) planes[k][i] = c[k] * s.strength * s.tint[k];
  }
  const int levels = plan_for(s, width, height).count;
  fft::convolve({&planes[0], &planes[1], &planes[2]}, W, H, psf::of_mode(s, levels, W, H));
  model::composite(color, W, H, frame_scale, s.nonfinite, output, [&](int x, int y, double add[3]) {
    const size_t i = static_cast<size_t>(y) * W + x;
    for (int k = 0; k < 3; ++k) add[k] = planes[k][i];
  });
}

}  // namespace pfx_bloom
