// Summary numbers of a frame's colour, for pfx-render's JSON "output" block and for tests.
#pragma once

#include <array>
#include <cstdint>

#include "image.hpp"

namespace pfx::app {

struct ImageStats {
  int width = 0;
  int height = 0;
  // Per channel R, G, B over that channel's finite values only. A channel with no finite value
  // reports 0 for all three, so the numbers are always valid JSON.
  std::array<double, 3> min{0.0, 0.0, 0.0};
  std::array<double, 3> max{0.0, 0.0, 0.0};
  std::array<double, 3> mean{0.0, 0.0, 0.0};
  // Pixels with at least one NaN or +/-inf among R, G, B (alpha is not looked at).
  std::uint64_t nonfinite = 0;
};

ImageStats compute_image_stats(const Image& img);

}  // namespace pfx::app
