// How far an effect's output is from a reference: relative RMSE over RGB, the same relative to the
// change the reference makes to the input (the error norm the speed-against-error plot uses: for an
// effect that adds a little light to a bright frame, the frame would otherwise hide the error),
// and the largest absolute difference.
#pragma once

#include <cstdint>
#include <vector>

namespace pfx::bench {

struct ErrorMetrics {
  double relative_rmse = 0;  // sqrt(sum (out - ref)^2 / sum ref^2) over finite RGB pairs
  double change_relative_rmse = -1;  // sqrt(sum (out - ref)^2 / sum (ref - in)^2); -1: no input given
  double max_abs = 0;
  uint64_t nonfinite = 0;    // RGB values where output or reference is not finite (excluded)
};

// input_rgba, when given, is what the effect was given (for change_relative_rmse); values where it
// is not finite count as 0 there.
ErrorMetrics compare_rgb(const std::vector<float>& output_rgba, const std::vector<float>& reference_rgba,
                         const std::vector<float>* input_rgba = nullptr);

}  // namespace pfx::bench
