#include "reference/dof_scatter_reference.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <thread>
#include <vector>

#include "reference/dof_inputs.hpp"

namespace pfx_dof {
namespace {

// A disc's weights summed over the integer grid, so each disc spreads exactly its pixel's colour.
// Radii are quantised to 1/64 px for the table; the coverage itself uses the exact radius, so the
// sum is off by far less than the quantisation suggests.
class DiscNorms {
 public:
  explicit DiscNorms(double max_radius) : sums_(static_cast<size_t>(std::ceil(max_radius * 64)) + 2, 0.0) {
    for (size_t i = 0; i < sums_.size(); ++i) sums_[i] = grid_sum(i / 64.0);
  }
  double operator()(double r) const {
    const double f = r * 64.0;
    const size_t i = std::min(static_cast<size_t>(f), sums_.size() - 2);
    const double t = f - double(i);
    return sums_[i] * (1 - t) + sums_[i + 1] * t;
  }

 private:
  static double grid_sum(double r) {
    const int reach = static_cast<int>(std::ceil(r + 0.5));
    double sum = 0;
    for (int y = -reach; y <= reach; ++y)
      for (int x = -reach; x <= reach; ++x) sum += disc_coverage(std::hypot(double(x), double(y)), r);
    return sum;
  }
  std::vector<double> sums_;
};

struct Contribution {
  double depth, weight;
  const Texel* color;
};

}  // namespace

void evaluate_scatter_reference(const Settings& settings, const pfx_frame& frame, const float* color,
                                const float* depth, float* output) {
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  const Texture sharp = safe_color(frame, color, settings.nonfinite);
  const std::vector<double> coc = coc_image(frame, frame_lens(frame, settings, depth), depth);
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<double> radius(n), order(n);
  double max_radius = 0.5;
  for (size_t i = 0; i < n; ++i) {
    radius[i] = std::max(0.5 * std::fabs(coc[i]), 0.5);
    max_radius = std::max(max_radius, radius[i]);
    // Front to back by view depth; a NaN depth (CoC 0) sorts as it decodes, last.
    const double d = view_depth(frame, depth[i]);
    order[i] = std::isnan(d) ? HUGE_VAL : d;
  }
  const DiscNorms norms(max_radius);
  std::vector<double> weight(n);
  for (size_t i = 0; i < n; ++i) weight[i] = 1.0 / norms(radius[i]);
  // The reach of the discs that can cover a pixel, per 16 px tile: most of a frame is far from the
  // largest blur, and looking only as far as needed keeps 1080p frames to seconds.
  const int tile = 16, tw = (w + tile - 1) / tile, th = (h + tile - 1) / tile;
  std::vector<double> tile_max(static_cast<size_t>(tw) * th, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double& m = tile_max[static_cast<size_t>(y / tile) * tw + x / tile];
      m = std::max(m, radius[static_cast<size_t>(y) * w + x]);
    }
  const int reach_tiles = static_cast<int>(std::ceil((max_radius + 0.5) / tile));
  std::vector<int> tile_reach(tile_max.size());
  for (int ty = 0; ty < th; ++ty)
    for (int tx = 0; tx < tw; ++tx) {
      double m = 0;
      for (int v = std::max(0, ty - reach_tiles); v <= std::min(th - 1, ty + reach_tiles); ++v)
        for (int u = std::max(0, tx - reach_tiles); u <= std::min(tw - 1, tx + reach_tiles); ++u)
          m = std::max(m, tile_max[static_cast<size_t>(v) * tw + u]);
      tile_reach[static_cast<size_t>(ty) * tw + tx] = static_cast<int>(std::ceil(m + 0.5));
    }

  auto row = [&](int y, std::vector<Contribution>& list) {
    for (int x = 0; x < w; ++x) {
      const int reach = tile_reach[static_cast<size_t>(y / tile) * tw + x / tile];
      list.clear();
      double total = 0;
      for (int v = std::max(0, y - reach); v <= std::min(h - 1, y + reach); ++v)
        for (int u = std::max(0, x - reach); u <= std::min(w - 1, x + reach); ++u) {
          const size_t q = static_cast<size_t>(v) * w + u;
          const double c = disc_coverage(std::hypot(double(u - x), double(v - y)), radius[q]);
          if (c <= 0) continue;
          list.push_back({order[q], c * weight[q], &sharp.texels[q]});
          total += c * weight[q];
        }
      // Only a pixel covered more than once over needs the depth order.
      if (total > 1.0) std::sort(list.begin(), list.end(), [](const Contribution& a, const Contribution& b) {
        return a.depth < b.depth;
      });
      double sum[3] = {0, 0, 0}, filled = 0;
      for (const Contribution& k : list) {
        const double take = std::min(k.weight, 1.0 - filled);
        if (take <= 0) break;
        for (int c = 0; c < 3; ++c) sum[c] += take * (*k.color)[c];
        filled += take;
      }
      const size_t i = static_cast<size_t>(y) * w + x;
      for (int c = 0; c < 3; ++c) output[i * 4 + c] = static_cast<float>(filled > 0 ? sum[c] / filled : 0.0);
      output[i * 4 + 3] = static_cast<float>(sharp.texels[i][3]);
    }
  };
  const int threads = std::max(1u, std::min(16u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  std::vector<char> failed(threads, 0);
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      try {
        std::vector<Contribution> list;
        for (int y = t; y < h; y += threads) row(y, list);
      } catch (...) {  // an exception may not leave a thread; the caller reports it
        failed[t] = 1;
      }
    });
  for (std::thread& th : pool) th.join();
  if (std::find(failed.begin(), failed.end(), 1) != failed.end()) throw std::bad_alloc();
}

}  // namespace pfx_dof
