// The halo around a sharp object: how wide a band just outside the object differs from
// the ground truth. Rings of one pixel are taken outward from the object's outline (Euclidean
// distance in (k - 1, k] for ring k); a ring belongs to the band when its mean error (the largest
// of |output - truth| over R, G, B) exceeds the tolerance. The width is the number of rings in the
// band before the first ring that does not; 0 when the first ring is already within tolerance.
#pragma once

#include <cstdint>
#include <vector>

namespace pfx::bench {

struct HaloMeasure {
  int width = 0;                    // px
  std::vector<double> ring_errors;  // mean error of rings 1, 2, ... (up to the search radius)
};

// output, truth: width * height RGBA; mask: width * height, non-zero on the object. Rings are
// looked at up to max_rings pixels out.
HaloMeasure measure_halo(const std::vector<float>& output, const std::vector<float>& truth,
                         const std::vector<uint8_t>& mask, int width, int height, double tolerance,
                         int max_rings = 32);

// Squared Euclidean distance of every pixel to the nearest non-zero pixel of mask (exact, in two
// passes of Felzenszwalb and Huttenlocher's 1D transform); +inf when the mask is empty.
std::vector<double> squared_distance_to(const std::vector<uint8_t>& mask, int width, int height);

}  // namespace pfx::bench
