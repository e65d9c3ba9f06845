#include "reference/dof_seed_model.hpp"

#include <algorithm>
#include <cmath>

#include "dof_seed_disk.hpp"
#include "reference/dof_inputs.hpp"

namespace pfx_dof {

void evaluate_seed_model(const Settings& settings, const pfx_frame& frame, const float* color, const float* depth,
                         float* output) {
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  const Texture sharp = safe_color(frame, color, settings.nonfinite);
  // The half-size copy: one bilinear tap at each half texel's centre (the 2x2 average on even sides).
  Texture half(half_size(w), half_size(h));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x)
      half.at(x, y) = sharp.bilinear((x + 0.5) / half.width, (y + 0.5) / half.height);
  store_half(&half);

  const std::vector<double> coc = coc_image(frame, frame_lens(frame, settings, depth), depth);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const Texel& c = sharp.fetch(x, y);
      Texel result = c;
      const double size = std::fabs(coc[i]);
      if (size > 1.0) {
        const double u = (x + 0.5) / w, v = (y + 0.5) / h;
        Texel blur{0, 0, 0, 0};
        for (const auto& tap : kSeedDisk) {
          const Texel t = half.bilinear(u + tap[0] * size / w, v + tap[1] * size / h);
          for (int k = 0; k < 3; ++k) blur[k] += t[k] / kSeedTaps;
        }
        const double amount = std::clamp(size - 1.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) result[k] = c[k] + (blur[k] - c[k]) * amount;
      }
      for (int k = 0; k < 4; ++k) output[i * 4 + k] = static_cast<float>(result[k]);
    }
}

}  // namespace pfx_dof
