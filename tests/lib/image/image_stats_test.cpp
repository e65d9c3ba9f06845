#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "image_stats.hpp"

TEST_CASE("image stats skip non-finite values and count the pixels holding them",
          "[image][stats]") {
  const float nan = std::nanf("");
  const float inf = std::numeric_limits<float>::infinity();
  pfx::app::Image img;
  img.width = 3;
  img.height = 2;
  img.rgba = {
      1.0f, 2.0f,  3.0f, 1.0f,  //
      nan,  4.0f,  -1.0f, 1.0f,  // NaN in R: counted once, G and B still used
      5.0f, inf,   0.0f, nan,   // inf in G; alpha NaN is not looked at
      3.0f, 0.0f,  1.0f, 1.0f,  //
      -inf, -inf,  nan,  1.0f,  // every channel non-finite: one pixel
      2.0f, 6.0f,  2.0f, inf,   // non-finite alpha only: still a finite pixel
  };
  const pfx::app::ImageStats s = pfx::app::compute_image_stats(img);
  CHECK(s.width == 3);
  CHECK(s.height == 2);
  CHECK(s.nonfinite == 3);
  CHECK(s.min == std::array<double, 3>{1.0, 0.0, -1.0});
  CHECK(s.max == std::array<double, 3>{5.0, 6.0, 3.0});
  CHECK(s.mean[0] == Approx((1.0 + 5.0 + 3.0 + 2.0) / 4));
  CHECK(s.mean[1] == Approx((2.0 + 4.0 + 0.0 + 6.0) / 4));
  CHECK(s.mean[2] == Approx((3.0 - 1.0 + 0.0 + 1.0 + 2.0) / 5));
}

TEST_CASE("image stats of an all-NaN channel report zeros", "[image][stats]") {
  pfx::app::Image img;
  img.width = 1;
  img.height = 2;
  img.rgba = {std::nanf(""), 0.5f, 0.25f, 1.0f, std::nanf(""), 1.5f, 0.75f, 1.0f};
  const pfx::app::ImageStats s = pfx::app::compute_image_stats(img);
  CHECK(s.nonfinite == 2);
  CHECK(s.min[0] == 0.0);
  CHECK(s.max[0] == 0.0);
  CHECK(s.mean[0] == 0.0);
  CHECK(s.min[1] == 0.5);
  CHECK(s.max[1] == 1.5);
  CHECK(s.mean[1] == Approx(1.0));
}
