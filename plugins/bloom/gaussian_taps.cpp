#include "gaussian_taps.hpp"

#include <algorithm>
#include <cmath>

#include "bloom_params.hpp"

namespace pfx_bloom {

void gaussian_weights(double deviation, int half_taps, double* weights) {
  const double d = std::max(deviation, 1e-3);
  double sum = 0;
  for (int k = 0; k <= half_taps; ++k) {
    weights[k] = std::exp(-0.5 * (k / d) * (k / d));
    sum += k == 0 ? weights[k] : 2.0 * weights[k];
  }
  for (int k = 0; k <= half_taps; ++k) weights[k] /= sum;
}

double gaussian_mode_deviation(const Settings& s) {
  const double d = s.downscale;
  const double variance = s.sigma * s.sigma - (d * d - 1.0) / 4.0;
  return std::sqrt(std::max(variance, 0.0)) / d;
}

}  // namespace pfx_bloom
