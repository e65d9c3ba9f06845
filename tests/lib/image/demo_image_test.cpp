#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "demo_image.hpp"
#include "image_stats.hpp"

TEST_CASE("demo image is deterministic and has depth for every pixel", "[image][demo]") {
  const pfx::app::Image a = pfx::app::make_demo_image(320, 180);
  const pfx::app::Image b = pfx::app::make_demo_image(320, 180);
  REQUIRE(a.width == 320);
  REQUIRE(a.height == 180);
  REQUIRE(a.is_consistent());
  REQUIRE(a.has_depth());
  CHECK(a.rgba == b.rgba);
  CHECK(a.depth == b.depth);
  for (float v : a.rgba) REQUIRE(std::isfinite(v));
  for (float d : a.depth) REQUIRE((d >= 1.0f && d <= 50.0f));
}

TEST_CASE("demo image has very bright spots for bloom", "[image][demo]") {
  const pfx::app::Image img = pfx::app::make_demo_image(320, 180);
  const pfx::app::ImageStats s = pfx::app::compute_image_stats(img);
  CHECK(s.max[0] >= 1000.0);
  CHECK(s.mean[0] < 10.0);  // the spots are small, the rest is ordinary
  std::size_t above_10 = 0, above_1 = 0;
  for (std::size_t i = 0; i < img.pixel_count(); ++i) {
    const float m = std::max({img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]});
    above_10 += m >= 10.0f;
    above_1 += m > 1.0f;
  }
  CHECK(above_10 >= 10);
  CHECK(above_1 < img.pixel_count() / 50);
}

TEST_CASE("demo image depth ramps from far at the top to near at the bottom, with objects",
          "[image][demo]") {
  const pfx::app::Image img = pfx::app::make_demo_image(320, 180);
  // Column 1 passes through no object: the pure background.
  CHECK(img.depth[1] == 50.0f);
  CHECK(img.depth[static_cast<std::size_t>(img.height - 1) * img.width + 1] < 1.1f);
  std::vector<float> distinct(img.depth.begin(), img.depth.end());
  for (float d : {1.5f, 2.5f, 4.0f, 5.0f, 8.0f, 25.0f}) {
    CHECK(std::count(distinct.begin(), distinct.end(), d) > 50);
  }
}

TEST_CASE("demo image has pixel-level detail for blur to remove", "[image][demo]") {
  const pfx::app::Image img = pfx::app::make_demo_image(320, 180);
  std::size_t sharp_edges = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x + 1 < img.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * img.width + x;
      sharp_edges += std::fabs(img.rgba[i * 4 + 1] - img.rgba[(i + 1) * 4 + 1]) > 0.5f;
    }
  }
  CHECK(sharp_edges > 2000);
}

TEST_CASE("demo image at tiny and odd sizes", "[image][demo]") {
  for (auto [w, h] : {std::pair{1, 1}, std::pair{2, 1}, std::pair{1917, 3}, std::pair{7, 1079}}) {
    const pfx::app::Image img = pfx::app::make_demo_image(w, h);
    INFO(w << "x" << h);
    CHECK(img.width == w);
    CHECK(img.height == h);
    CHECK(img.is_consistent());
    for (float v : img.rgba) REQUIRE(std::isfinite(v));
  }
  CHECK(pfx::app::make_demo_image(0, 10).pixel_count() == 0);
  CHECK(pfx::app::make_demo_image(-3, 10).rgba.empty());
}
