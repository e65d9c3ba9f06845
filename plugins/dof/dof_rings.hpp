// The gather's sample set: N points over the unit disc in concentric rings, each with the area of
// the disc it stands for (they sum to pi), so a gather can weigh samples by area and keep energy
// constant whatever N is. Ring k of K holds samples in proportion to its area (2k - 1) / K^2, at the
// radius that splits the ring's area in half; alternate rings are turned by half a step.
// K = round(sqrt(N) / 2): 16 -> 2 rings (4 + 12), 64 -> 4 (4, 12, 20, 28), 256 -> 8.
#pragma once

#include <vector>

namespace pfx_dof {

struct RingSample {
  float x, y;  // in the unit disc
  float area;  // of the unit disc's area pi
};

std::vector<RingSample> ring_samples(int count);

// Every texel offset within kDiscOffsetCount of the centre (the centre itself left out), nearest
// first (ties by angle, so the order is fixed): a gather whose disc holds no more texels than its
// sample budget reads exactly these, each standing for its own pixel, and its kernel is then the
// exact disc instead of rounded ring positions.
constexpr int kDiscOffsetCount = 256;
struct DiscOffset {
  int x, y;
  float length;
};
const std::vector<DiscOffset>& disc_offsets();

}  // namespace pfx_dof
