#include "dof_gather_plan.hpp"

#include <cmath>

namespace pfx_dof {

GatherPlan plan_gather(uint32_t frame_width, uint32_t frame_height, const Settings& s) {
  GatherPlan plan;
  plan.half = s.resolution == RESOLUTION_HALF;
  const int w = static_cast<int>(frame_width), h = static_cast<int>(frame_height);
  // Odd sides round up, so every frame pixel has its 2x2 block's half texel.
  plan.work_width = plan.half ? (w + 1) / 2 : w;
  plan.work_height = plan.half ? (h + 1) / 2 : h;
  plan.tile = plan.half ? kTileFramePixels / 2 : kTileFramePixels;
  plan.tiles_width = (plan.work_width + plan.tile - 1) / plan.tile;
  plan.tiles_height = (plan.work_height + plan.tile - 1) / plan.tile;
  plan.dilation = static_cast<int>(std::ceil(0.5 * s.max_coc / kTileFramePixels));
  return plan;
}

}  // namespace pfx_dof
