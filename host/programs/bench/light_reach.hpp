// How many of the lights brute force sums at a pixel could change that pixel: the least any exact
// method must sum there, so brute force's lights over that mean is the most any exact method can
// gain over brute force on that frame, whatever its lists. Two counts per pixel:
//   reaching: the light's range reaches the pixel's point (d < range), the bound a culling by
//             light volumes can approach;
//   lit:      of those, the lights whose term is not zero: radiance > 0 and the light in front of
//             the surface (N.L > 0, or the light at the point itself), the bound any exact method
//             has, since a term that is not zero changes the sum.
// And one count per square tile, for what one list per tile costs even when culled perfectly: the
// lights reaching some point of the pixel's tile, each pixel summing its tile's list.
// Light ranges follow tiledlights' default cutoff rule (an explicit range > 0, else where
// intensity x max(colour) / (1 + d^2) falls to the cutoff). Computed here in double precision from
// the frame and its G-buffer alone, so a culling bug cannot hide in it; a term within rounding of a
// boundary may count on one side here and fall on the other on the GPU.
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/effect.h>

namespace pfx::bench {

struct LightReach {
  uint64_t pixels = 0;      // pixels with geometry (a positive finite view depth)
  double reaching_mean = 0; // means over those pixels; 0 when there are none
  double lit_mean = 0;
  double tile_reaching_mean = 0;  // per pixel with geometry, the lights reaching a point of its tile
};

// depth: the frame's stored depth, one float per pixel; normal: the G-buffer's world-space normals,
// four floats per pixel; both rows bottom first. The view matrix must be rigid (rotation and
// translation), as a camera's is. Tiles are tile x tile pixels from the bottom-left corner (as
// tiledlights' tiled mode lays them), tile >= 1.
LightReach count_light_reach(const pfx_frame& frame, const std::vector<float>& depth, const std::vector<float>& normal,
                             double cutoff, int tile);

}  // namespace pfx::bench
