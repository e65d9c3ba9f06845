// The bloom pyramid's level count and sizes, shared by declare (GPU) and the CPU references so both
// always build the same pyramid.
//
// chain and chain13: level 0 is half the frame and every next level half the previous, rounded
// down as the seed does (1920x1080 -> 960x540 -> 480x270 ...). mgf: the same from a quarter of the
// frame (480x270 -> 240x135 ...), as seed 004's buffers. Never below one pixel: a 1x1 or 2x3 frame
// still gets a 1x1 level. A pyramid stops at the first level that is 1x1, since more 1x1 levels would
// only repeat it; asking for more levels than that is clamped, not refused.
#pragma once

#include <cstdint>

namespace pfx_bloom {

struct Settings;

constexpr int kMaxLevels = 16;

struct LevelPlan {
  int count = 0;
  int width[kMaxLevels] = {};
  int height[kMaxLevels] = {};
};

// The most levels a frame of this size allows (>= 1), level 0 being the frame / first_divisor.
int max_levels(uint32_t frame_width, uint32_t frame_height, int first_divisor = 2);

// requested: 1..16 levels, or 0 for automatic: as many as keep the shorter side of the smallest
// level at auto_min_size pixels or more (at least one level). The result is clamped to max_levels.
LevelPlan plan_levels(uint32_t frame_width, uint32_t frame_height, int requested, int auto_min_size,
                      int first_divisor = 2);

// The plan of the settings' mode: plan_levels with the mode's first divisor, and with levels 0 also
// the share rule (no level that would carry less than auto_min_share of the light; see
// level_weights). The gaussian mode has one level: the frame / downscale.
LevelPlan plan_for(const Settings& settings, uint32_t frame_width, uint32_t frame_height);

// Each level's share of the bloom's light (they sum to 1): 1/count for the chains; for mgf
// ratio^i normalised. out has count entries.
void level_weights(const Settings& settings, int count, double* out);

}  // namespace pfx_bloom
