#include "error_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::bench {

ErrorMetrics compare_rgb(const std::vector<float>& output, const std::vector<float>& reference,
                         const std::vector<float>* input) {
  ErrorMetrics metrics;
  double squared_error = 0, squared_reference = 0, squared_change = 0;
  const size_t n = std::min(output.size(), reference.size());
  for (size_t i = 0; i < n; ++i) {
    if (i % 4 == 3) continue;  // alpha
    double o = output[i], r = reference[i];
    if (!std::isfinite(o) || !std::isfinite(r)) {
      ++metrics.nonfinite;
      continue;
    }
    squared_error += (o - r) * (o - r);
    squared_reference += r * r;
    if (input && i < input->size()) {
      const double in = std::isfinite((*input)[i]) ? (*input)[i] : 0.0;
      squared_change += (r - in) * (r - in);
    }
    metrics.max_abs = std::max(metrics.max_abs, std::abs(o - r));
  }
  metrics.relative_rmse = squared_reference > 0 ? std::sqrt(squared_error / squared_reference)
                                                : std::sqrt(squared_error);
  if (input) metrics.change_relative_rmse = squared_change > 0 ? std::sqrt(squared_error / squared_change) : 0.0;
  return metrics;
}

}  // namespace pfx::bench
