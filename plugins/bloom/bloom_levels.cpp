#include "bloom_levels.hpp"

#include <algorithm>
#include <cmath>

#include "bloom_params.hpp"

namespace pfx_bloom {
namespace {

int fraction_of(int size, int divisor) { return std::max(1, size / divisor); }

void set_block_grid(LevelPlan& plan, uint32_t frame_width, uint32_t frame_height, int block) {
  const int w = static_cast<int>(frame_width), h = static_cast<int>(frame_height);
  plan.block = block;
  plan.pad_x = padding_before(w, block);
  plan.pad_y = padding_before(h, block);
  plan.width[0] = blocks_covering(w, block);
  plan.height[0] = blocks_covering(h, block);
  for (int i = 1; i < plan.count; ++i) {
    plan.width[i] = blocks_covering(plan.width[i - 1], 2);
    plan.height[i] = blocks_covering(plan.height[i - 1], 2);
  }
}

}  // namespace

int blocks_covering(int frame, int block) { return std::max(1, (frame + block - 1) / block); }

int padding_before(int frame, int block) { return (blocks_covering(frame, block) * block - frame) / 2; }

int max_levels(uint32_t frame_width, uint32_t frame_height, int first_divisor) {
  int w = fraction_of(static_cast<int>(frame_width), first_divisor);
  int h = fraction_of(static_cast<int>(frame_height), first_divisor);
  int count = 1;
  while ((w > 1 || h > 1) && count < kMaxLevels) {
    w = fraction_of(w, 2);
    h = fraction_of(h, 2);
    ++count;
  }
  return count;
}

LevelPlan plan_levels(uint32_t frame_width, uint32_t frame_height, int requested, int auto_min_size,
                      int first_divisor) {
  LevelPlan plan;
  const int limit = max_levels(frame_width, frame_height, first_divisor);
  int w = fraction_of(static_cast<int>(frame_width), first_divisor);
  int h = fraction_of(static_cast<int>(frame_height), first_divisor);
  for (int i = 0; i < limit; ++i) {
    const bool automatic = requested <= 0;
    if (automatic && i > 0 && std::min(w, h) < auto_min_size) break;
    if (!automatic && i >= requested) break;
    plan.width[i] = w;
    plan.height[i] = h;
    plan.count = i + 1;
    w = fraction_of(w, 2);
    h = fraction_of(h, 2);
  }
  return plan;
}

void level_weights(const Settings& s, int count, double* out) {
  double sum = 0;
  for (int i = 0; i < count; ++i) sum += out[i] = s.mode == MODE_MGF ? std::pow(s.mgf_ratio, i) : 1.0;
  for (int i = 0; i < count; ++i) out[i] /= sum;
}

LevelPlan plan_for(const Settings& s, uint32_t frame_width, uint32_t frame_height) {
  if (s.mode == MODE_GAUSSIAN) {
    LevelPlan plan;
    plan.count = 1;
    set_block_grid(plan, frame_width, frame_height, s.downscale);
    return plan;
  }
  const bool mgf = s.mode == MODE_MGF;
  LevelPlan plan = plan_levels(frame_width, frame_height, s.levels, s.auto_min_size, mgf ? 4 : 2);
  if (s.levels <= 0 && s.auto_min_share > 0) {
    // The share rule: stop before the first level whose own share would fall below the minimum.
    for (int n = 2; n <= plan.count; ++n) {
      double weights[kMaxLevels];
      level_weights(s, n, weights);
      if (weights[n - 1] < s.auto_min_share) {
        plan.count = n - 1;
        break;
      }
    }
  }
  if (mgf) set_block_grid(plan, frame_width, frame_height, 4);
  return plan;
}

}  // namespace pfx_bloom
