#include "dof_rings.hpp"

#include <algorithm>
#include <cmath>

namespace pfx_dof {

std::vector<RingSample> ring_samples(int count) {
  count = std::max(count, 1);
  const int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(double(count)) / 2.0)));
  // Largest remainder: every ring gets floor of its share, the largest fractions get one more.
  std::vector<int> per_ring(rings);
  std::vector<std::pair<double, int>> fractions;
  int given = 0;
  for (int k = 1; k <= rings; ++k) {
    const double share = double(count) * (2 * k - 1) / double(rings * rings);
    per_ring[k - 1] = static_cast<int>(std::floor(share));
    given += per_ring[k - 1];
    fractions.push_back({share - std::floor(share), k - 1});
  }
  std::stable_sort(fractions.begin(), fractions.end(), [](auto a, auto b) { return a.first > b.first; });
  for (int i = 0; given < count; ++i, ++given) ++per_ring[fractions[i % rings].second];
  std::vector<RingSample> samples;
  for (int k = 1; k <= rings; ++k) {
    const int n = per_ring[k - 1];
    if (n == 0) continue;
    const double inner = double(k - 1) / rings, outer = double(k) / rings;
    const double radius = std::sqrt(0.5 * (inner * inner + outer * outer));
    const double area = M_PI * (outer * outer - inner * inner) / n;
    const double turn = (k % 2 == 0) ? 0.5 : 0.0;
    for (int j = 0; j < n; ++j) {
      const double angle = 2.0 * M_PI * (j + turn) / n;
      samples.push_back({static_cast<float>(radius * std::cos(angle)), static_cast<float>(radius * std::sin(angle)),
                         static_cast<float>(area)});
    }
  }
  return samples;
}

const std::vector<DiscOffset>& disc_offsets() {
  static const std::vector<DiscOffset> offsets = [] {
    std::vector<DiscOffset> all;
    for (int y = -12; y <= 12; ++y)
      for (int x = -12; x <= 12; ++x)
        if (x || y) all.push_back({x, y, static_cast<float>(std::hypot(double(x), double(y)))});
    std::stable_sort(all.begin(), all.end(), [](const DiscOffset& a, const DiscOffset& b) {
      if (a.length != b.length) return a.length < b.length;
      return std::atan2(double(a.y), double(a.x)) < std::atan2(double(b.y), double(b.x));
    });
    all.resize(kDiscOffsetCount);
    return all;
  }();
  return offsets;
}

}  // namespace pfx_dof
