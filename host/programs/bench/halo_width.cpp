#include "halo_width.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::bench {
namespace {

// The lower envelope of parabolas (q - p)^2 + f[p]: f holds squared distances along one line.
void distance_1d(std::vector<double>& f) {
  const int n = static_cast<int>(f.size());
  std::vector<double> d(n), z(n + 1);
  std::vector<int> v(n);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (std::isinf(f[q])) continue;
    double s = -HUGE_VAL;
    while (k >= 0) {
      s = ((f[q] + double(q) * q) - (f[v[k]] + double(v[k]) * v[k])) / (2.0 * (q - v[k]));
      if (s > z[k]) break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -HUGE_VAL : s;
    z[k + 1] = HUGE_VAL;
  }
  if (k < 0) return;  // no finite value on this line
  for (int q = 0, j = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    d[q] = double(q - v[j]) * (q - v[j]) + f[v[j]];
  }
  f = d;
}

}  // namespace

std::vector<double> squared_distance_to(const std::vector<uint8_t>& mask, int width, int height) {
  std::vector<double> dist(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) dist[i] = mask[i] ? 0.0 : HUGE_VAL;
  std::vector<double> line;
  for (int x = 0; x < width; ++x) {
    line.resize(height);
    for (int y = 0; y < height; ++y) line[y] = dist[static_cast<size_t>(y) * width + x];
    distance_1d(line);
    for (int y = 0; y < height; ++y) dist[static_cast<size_t>(y) * width + x] = line[y];
  }
  for (int y = 0; y < height; ++y) {
    line.assign(dist.begin() + static_cast<long>(y) * width, dist.begin() + static_cast<long>(y + 1) * width);
    distance_1d(line);
    std::copy(line.begin(), line.end(), dist.begin() + static_cast<long>(y) * width);
  }
  return dist;
}

HaloMeasure measure_halo(const std::vector<float>& output, const std::vector<float>& truth,
                         const std::vector<uint8_t>& mask, int width, int height, double tolerance, int max_rings) {
  HaloMeasure m;
  const std::vector<double> dist = squared_distance_to(mask, width, height);
  std::vector<double> sum(max_rings, 0.0);
  std::vector<size_t> count(max_rings, 0);
  for (size_t i = 0; i < dist.size(); ++i) {
    if (mask[i] || std::isinf(dist[i])) continue;
    const int ring = static_cast<int>(std::ceil(std::sqrt(dist[i]))) - 1;  // distance in (k-1, k] -> k-1
    if (ring >= max_rings) continue;
    double error = 0;
    for (int c = 0; c < 3; ++c) error = std::max(error, std::fabs(double(output[i * 4 + c]) - double(truth[i * 4 + c])));
    sum[ring] += std::isfinite(error) ? error : HUGE_VAL;
    ++count[ring];
  }
  bool in_band = true;
  for (int k = 0; k < max_rings && count[k] > 0; ++k) {
    const double mean = sum[k] / count[k];
    m.ring_errors.push_back(mean);
    if (in_band && mean > tolerance) ++m.width;
    else in_band = false;
  }
  return m;
}

}  // namespace pfx::bench
