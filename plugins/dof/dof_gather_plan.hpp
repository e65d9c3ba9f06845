// The sizes the "gather" mode works at, from the frame size and the settings: shared by declare
// (which turns them into targets) and by the CPU model (which must use the very same ones).
#pragma once

#include <cstdint>

#include "dof_params.hpp"

namespace pfx_dof {

// A tile covers 16 x 16 frame pixels (Filament's tile size).
constexpr int kTileFramePixels = 16;

struct GatherPlan {
  bool half = false;          // gather at half resolution, composite at full
  int work_width = 0, work_height = 0;
  int tile = 0;               // work pixels per tile side: 16 at full resolution, 8 at half
  int tiles_width = 0, tiles_height = 0;
  int dilation = 0;           // tiles each way a blurred foreground may reach: ceil(max_coc / 2 / 16)
};

GatherPlan plan_gather(uint32_t frame_width, uint32_t frame_height, const Settings& settings);

}  // namespace pfx_dof
