// How far an effect's output is from a reference: relative RMSE over RGB (the error norm the
// speed-against-error plots use) and the largest absolute difference.
#pragma once

#include <cstdint>
#include <vector>

namespace pfx::bench {

struct ErrorMetrics {
  double relative_rmse = 0;  // sqrt(sum (out - ref)^2 / sum ref^2) over finite RGB pairs
  double max_abs = 0;
  uint64_t nonfinite = 0;    // RGB values where output or reference is not finite (excluded)
};

ErrorMetrics compare_rgb(const std::vector<float>& output_rgba, const std::vector<float>& reference_rgba);

}  // namespace pfx::bench
