#include "image_stats.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::app {

ImageStats compute_image_stats(const Image& img) {
  ImageStats s;
  s.width = img.width;
  s.height = img.height;
  if (!img.is_consistent()) return s;

  std::array<double, 3> lo{}, hi{}, sum{};
  std::array<std::uint64_t, 3> count{};
  for (std::size_t i = 0; i < img.pixel_count(); ++i) {
    bool bad = false;
    for (int c = 0; c < 3; ++c) {
      const float v = img.rgba[i * 4 + c];
      if (!std::isfinite(v)) {
        bad = true;
        continue;
      }
      if (count[c] == 0) {
        lo[c] = hi[c] = v;
      } else {
        lo[c] = std::min(lo[c], static_cast<double>(v));
        hi[c] = std::max(hi[c], static_cast<double>(v));
      }
      // Double accumulation keeps the mean of a 4K frame accurate to far below half precision.
      sum[c] += v;
      ++count[c];
    }
    if (bad) ++s.nonfinite;
  }
  for (int c = 0; c < 3; ++c) {
    if (count[c] == 0) continue;
    s.min[c] = lo[c];
    s.max[c] = hi[c];
    s.mean[c] = sum[c] / static_cast<double>(count[c]);
  }
  return s;
}

}  // namespace pfx::app
