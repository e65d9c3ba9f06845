#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <Imath/half.h>

#include "exr_io.hpp"
#include "test_files.hpp"

using pfx::app::ExrPixelType;
using pfx::app::Image;

namespace {

// Odd sizes catch stride and row-order mistakes that square powers of two hide.
Image make_test_image(int w, int h, bool with_depth) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.resize(img.pixel_count() * 4);
  // Magnitudes from half-denormal to well above 1, both signs, no two pixels alike.
  const float scales[] = {1e-5f, 0.01f, 1.0f, 37.0f, 1000.0f, -0.5f};
  for (std::size_t i = 0; i < img.rgba.size(); ++i) {
    const float frac = std::fmod(static_cast<float>(i) * 0.6180339f, 1.0f);
    img.rgba[i] = frac * scales[i % 6];
  }
  if (with_depth) {
    img.depth.resize(img.pixel_count());
    for (std::size_t i = 0; i < img.depth.size(); ++i) img.depth[i] = 0.1f + 0.3719f * i;
  }
  return img;
}

float as_half(float v) { return static_cast<float>(half(v)); }

}  // namespace

TEST_CASE("EXR half round trip keeps RGBA to half precision and Z exactly", "[image][exr]") {
  pfx_test::TempDir dir;
  const Image src = make_test_image(37, 19, true);
  const std::string path = dir.file("half.exr");
  std::string error;
  REQUIRE(pfx::app::write_exr(path, src, ExrPixelType::Half, &error));
  CHECK(error.empty());

  Image back;
  REQUIRE(pfx::app::read_exr(path, &back, &error));
  REQUIRE(back.width == 37);
  REQUIRE(back.height == 19);
  REQUIRE(back.rgba.size() == src.rgba.size());
  REQUIRE(back.depth.size() == src.depth.size());
  for (std::size_t i = 0; i < src.rgba.size(); ++i) {
    INFO("value " << i << " was " << src.rgba[i]);
    CHECK(back.rgba[i] == as_half(src.rgba[i]));
  }
  for (std::size_t i = 0; i < src.depth.size(); ++i) CHECK(back.depth[i] == src.depth[i]);
}

TEST_CASE("EXR float round trip is exact, including Z", "[image][exr]") {
  pfx_test::TempDir dir;
  const Image src = make_test_image(37, 19, true);
  const std::string path = dir.file("float.exr");
  std::string error;
  REQUIRE(pfx::app::write_exr(path, src, ExrPixelType::Float, &error));
  Image back;
  REQUIRE(pfx::app::read_exr(path, &back, &error));
  CHECK(back.width == 37);
  CHECK(back.height == 19);
  CHECK(back.rgba == src.rgba);
  CHECK(back.depth == src.depth);
}

TEST_CASE("EXR without depth reads back without depth", "[image][exr]") {
  pfx_test::TempDir dir;
  const Image src = make_test_image(5, 3, false);
  const std::string path = dir.file("nodepth.exr");
  std::string error;
  REQUIRE(pfx::app::write_exr(path, src, ExrPixelType::Float, &error));
  Image back;
  REQUIRE(pfx::app::read_exr(path, &back, &error));
  CHECK_FALSE(back.has_depth());
  CHECK(back.rgba == src.rgba);
}

TEST_CASE("EXR half storage: values beyond 65504 become inf, NaN and inf survive", "[image][exr]") {
  pfx_test::TempDir dir;
  Image src;
  src.width = 2;
  src.height = 1;
  const float inf = std::numeric_limits<float>::infinity();
  src.rgba = {1e6f, -1e6f, inf, 1.0f, std::nanf(""), -inf, 65504.0f, 0.0f};
  const std::string path = dir.file("extremes.exr");
  std::string error;
  REQUIRE(pfx::app::write_exr(path, src, ExrPixelType::Half, &error));
  Image back;
  REQUIRE(pfx::app::read_exr(path, &back, &error));
  CHECK(back.rgba[0] == inf);
  CHECK(back.rgba[1] == -inf);
  CHECK(back.rgba[2] == inf);
  CHECK(back.rgba[3] == 1.0f);
  CHECK(std::isnan(back.rgba[4]));
  CHECK(back.rgba[5] == -inf);
  CHECK(back.rgba[6] == 65504.0f);
  CHECK(back.rgba[7] == 0.0f);

  // In float the same values are kept as they are.
  REQUIRE(pfx::app::write_exr(path, src, ExrPixelType::Float, &error));
  REQUIRE(pfx::app::read_exr(path, &back, &error));
  CHECK(back.rgba[0] == 1e6f);
  CHECK(back.rgba[1] == -1e6f);
  CHECK(std::isnan(back.rgba[4]));
}

TEST_CASE("write_exr refuses an image whose data does not match its size", "[image][exr]") {
  pfx_test::TempDir dir;
  Image bad;
  bad.width = 4;
  bad.height = 4;
  bad.rgba.resize(10);
  std::string error;
  CHECK_FALSE(pfx::app::write_exr(dir.file("bad.exr"), bad, ExrPixelType::Half, &error));
  CHECK_THAT(error, Catch::Contains("bad.exr"));
  CHECK(dir.entries().empty());

  Image empty;
  CHECK_FALSE(pfx::app::write_exr(dir.file("empty.exr"), empty, ExrPixelType::Half, &error));
  CHECK(dir.entries().empty());
}
