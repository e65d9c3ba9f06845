// The bloom pyramid's level count and sizes, shared by declare (GPU) and the CPU references so both
// always build the same pyramid.
//
// chain and chain13: level 0 is half the frame and every next level half the previous, rounded
// down (1920x1080 -> 960x540 -> 480x270 ...), each level resampled from the one before across
// its whole extent. Never below one pixel: a 1x1 or 2x3 frame still gets a 1x1
// level. A pyramid stops at the first level that is 1x1, since more 1x1 levels would only repeat
// it; asking for more levels than that is clamped, not refused.
//
// gaussian and mgf (and glare's buffer) average blocks of d x d pixels instead, d the downscale
// (mgf: 4, then 8, 16 ...). Rounding their size down would leave `size mod d` rows and columns
// that no block reads, so these buffers are rounded up: ceil(size / d) blocks cover the frame,
// which sits centred on them (the padding, fewer than d pixels, split with the smaller half
// before), and the padding counts as black. Every pixel then adds 1/d^2 of its light to exactly
// one texel, at any size. mgf's buffer i + 1 has ceil(n_i / 2) texels, each the 2x2 texels of
// buffer i that it covers (black past its edge). The level count is still the pyramid's (counted on
// the rounded-down sizes), so the number of Gaussians, and the ideal, do not depend on the padding.
#pragma once

#include <cstdint>

namespace pfx_bloom {

struct Settings;

constexpr int kMaxLevels = 16;

struct LevelPlan {
  int count = 0;
  int width[kMaxLevels] = {};
  int height[kMaxLevels] = {};
  // Block grids (gaussian, mgf): frame pixels per texel of level 0 (0 for the chains), and the
  // padding before the frame: texel (0, 0) of level 0 starts at frame pixel (-pad_x, -pad_y).
  // Level i's texels are 2^i texels of level 0.
  int block = 0;
  int pad_x = 0, pad_y = 0;
};

// The blocks of `block` pixels that cover `frame` pixels: ceil(frame / block), at least one.
int blocks_covering(int frame, int block);
// The padding before the frame when it is centred on those blocks (the smaller half, < block).
int padding_before(int frame, int block);

// The most levels a frame of this size allows (>= 1), level 0 being the frame / first_divisor.
int max_levels(uint32_t frame_width, uint32_t frame_height, int first_divisor = 2);

// requested: 1..16 levels, or 0 for automatic: as many as keep the shorter side of the smallest
// level at auto_min_size pixels or more (at least one level). The result is clamped to max_levels.
LevelPlan plan_levels(uint32_t frame_width, uint32_t frame_height, int requested, int auto_min_size,
                      int first_divisor = 2);

// The plan of the settings' mode: plan_levels with the mode's first divisor, and with levels 0 also
// the share rule (no level that would carry less than auto_min_share of the light; see
// level_weights). The gaussian mode has one level: the frame / downscale, rounded up.
LevelPlan plan_for(const Settings& settings, uint32_t frame_width, uint32_t frame_height);

// Each level's share of the bloom's light (they sum to 1): 1/count for the chains; for mgf
// ratio^i normalised. out has count entries.
void level_weights(const Settings& settings, int count, double* out);

}  // namespace pfx_bloom
