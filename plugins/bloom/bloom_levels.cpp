#include "bloom_levels.hpp"

#include <algorithm>

namespace pfx_bloom {
namespace {

int half_of(int size) { return std::max(1, size / 2); }

}  // namespace

int max_levels(uint32_t frame_width, uint32_t frame_height) {
  int w = half_of(static_cast<int>(frame_width)), h = half_of(static_cast<int>(frame_height));
  int count = 1;
  while ((w > 1 || h > 1) && count < kMaxLevels) {
    w = half_of(w);
    h = half_of(h);
    ++count;
  }
  return count;
}

LevelPlan plan_levels(uint32_t frame_width, uint32_t frame_height, int requested, int auto_min_size) {
  LevelPlan plan;
  const int limit = max_levels(frame_width, frame_height);
  int w = half_of(static_cast<int>(frame_width)), h = half_of(static_cast<int>(frame_height));
  for (int i = 0; i < limit; ++i) {
    const bool automatic = requested <= 0;
    if (automatic && i > 0 && std::min(w, h) < auto_min_size) break;
    if (!automatic && i >= requested) break;
    plan.width[i] = w;
    plan.height[i] = h;
    plan.count = i + 1;
    w = half_of(w);
    h = half_of(h);
  }
  return plan;
}

}  // namespace pfx_bloom
