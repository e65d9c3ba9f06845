// The bloom pyramid's level count and sizes, shared by declare (GPU) and the CPU reference so both
// always build the same pyramid.
//
// Level 0 is half the frame and every next level half the previous, rounded down as the seed does
// (1920x1080 -> 960x540 -> 480x270 ...), but never below one pixel: a 1x1 or 2x3 frame still gets a
// 1x1 level. A pyramid stops at the first level that is 1x1, since more 1x1 levels would only
// repeat it; asking for more levels than that is clamped, not refused.
#pragma once

#include <cstdint>

namespace pfx_bloom {

constexpr int kMaxLevels = 16;

struct LevelPlan {
  int count = 0;
  int width[kMaxLevels] = {};
  int height[kMaxLevels] = {};
};

// The most levels a frame of this size allows (>= 1).
int max_levels(uint32_t frame_width, uint32_t frame_height);

// requested: 1..16 levels, or 0 for automatic: as many as keep the shorter side of the smallest
// level at auto_min_size pixels or more (at least one level). The result is clamped to max_levels.
LevelPlan plan_levels(uint32_t frame_width, uint32_t frame_height, int requested, int auto_min_size);

}  // namespace pfx_bloom
