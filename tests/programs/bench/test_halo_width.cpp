// The halo measure of pfx-bench (halo_width.hpp): the exact distance transform against brute force,
// and the band width on halos of known width.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "halo_width.hpp"

using pfx::bench::measure_halo;
using pfx::bench::squared_distance_to;

TEST_CASE("the distance transform is exact", "[bench][halo]") {
  const int w = 23, h = 17;
  std::vector<uint8_t> mask(w * h, 0);
  mask[3 * w + 4] = mask[12 * w + 18] = mask[16 * w + 0] = 1;
  for (int x = 8; x < 12; ++x) mask[8 * w + x] = 1;
  const std::vector<double> d = squared_distance_to(mask, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double best = HUGE_VAL;
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u)
          if (mask[v * w + u]) best = std::min(best, double((x - u) * (x - u) + (y - v) * (y - v)));
      REQUIRE(d[y * w + x] == best);
    }
  CHECK(std::isinf(squared_distance_to(std::vector<uint8_t>(6, 0), 3, 2)[0]));
}

TEST_CASE("the halo width is the band of rings whose mean error passes the tolerance", "[bench][halo]") {
  const int w = 40, h = 40;
  std::vector<uint8_t> mask(w * h, 0);
  for (int y = 15; y < 25; ++y)
    for (int x = 15; x < 25; ++x) mask[y * w + x] = 1;
  const std::vector<double> d = squared_distance_to(mask, w, h);
  std::vector<float> truth(w * h * 4, 0.1f);
  for (int band : {0, 1, 3, 6}) {
    std::vector<float> output = truth;
    for (int i = 0; i < w * h; ++i)
      if (!mask[i] && std::sqrt(d[i]) <= band) output[i * 4 + 1] += 0.3f;  // the object's colour leaking out
    const auto halo = measure_halo(output, truth, mask, w, h, 0.05);
    CHECK(halo.width == band);
    REQUIRE(halo.ring_errors.size() >= 8);
    CHECK(halo.ring_errors[band] == Approx(0.0).margin(1e-6));
  }
  // Error far from the object is not a halo.
  std::vector<float> output = truth;
  for (int i = 0; i < w * h; ++i)
    if (std::sqrt(d[i]) > 5) output[i * 4] = 1.0f;
  CHECK(measure_halo(output, truth, mask, w, h, 0.05).width == 0);
}
