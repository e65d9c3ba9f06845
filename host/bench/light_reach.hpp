// How many lights really reach the surface seen at each pixel: the least any exact culling can
// sum there, so brute force's lights over its mean is the most any exact method can gain over brute
// force on that frame, whatever its lists. Light ranges follow tiledlights' default cutoff rule
// (an explicit range > 0, else where intensity x max(colour) / (1 + d^2) falls to the cutoff).
#pragma once

#include <vector>

#include <pfx/effect.h>

namespace pfx::bench {

// The mean over pixels with geometry (a positive finite view depth) of the lights whose range
// reaches the pixel's point. depth: the frame's stored depth, one float per pixel, rows bottom
// first. 0 when no pixel has geometry.
double mean_lights_reaching(const pfx_frame& frame, const std::vector<float>& depth, double cutoff);

}  // namespace pfx::bench
