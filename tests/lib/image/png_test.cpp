#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "png_io.hpp"
#include "test_files.hpp"

using pfx::app::DisplayImage;

namespace {

DisplayImage pattern(int w, int h, int channels) {
  DisplayImage img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.pixels.resize(static_cast<std::size_t>(w) * h * channels);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = static_cast<std::uint8_t>(i * 37 + 11);
  return img;
}

bool contains(const std::vector<char>& bytes, const std::string& s) {
  return std::search(bytes.begin(), bytes.end(), s.begin(), s.end()) != bytes.end();
}

}  // namespace

TEST_CASE("PNG RGB write and read back keeps every pixel, row 0 on top", "[image][png]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("rgb.png");
  const DisplayImage src = pattern(7, 5, 3);
  std::string error;
  REQUIRE(pfx::app::write_png(path, src, &error));

  const std::vector<char> bytes = pfx_test::read_bytes(path);
  REQUIRE(bytes.size() > 8);
  CHECK(std::string(bytes.data() + 1, 3) == "PNG");
  CHECK(contains(bytes, "sRGB"));  // viewers must not guess the encoding

  DisplayImage back;
  REQUIRE(pfx::app::read_png(path, &back, &error));
  CHECK(back.width == 7);
  CHECK(back.height == 5);
  CHECK(back.channels == 3);
  CHECK(back.pixels == src.pixels);
}

TEST_CASE("PNG RGBA write and read back keeps alpha", "[image][png]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("rgba.png");
  const DisplayImage src = pattern(3, 4, 4);
  std::string error;
  REQUIRE(pfx::app::write_png(path, src, &error));
  DisplayImage back;
  REQUIRE(pfx::app::read_png(path, &back, &error));
  CHECK(back.channels == 4);
  CHECK(back.pixels == src.pixels);
}

TEST_CASE("PNG read refuses missing, non-PNG and oversized files with the file name",
          "[image][png]") {
  pfx_test::TempDir dir;
  DisplayImage img;
  std::string error;

  CHECK_FALSE(pfx::app::read_png(dir.file("missing.png"), &img, &error));
  CHECK_THAT(error, Catch::Contains("missing.png") && Catch::Contains("no such file"));

  pfx_test::write_text(dir.file("text.png"), "plain text");
  CHECK_FALSE(pfx::app::read_png(dir.file("text.png"), &img, &error));
  CHECK_THAT(error, Catch::Contains("text.png") && Catch::Contains("not a readable PNG"));

  REQUIRE(pfx::app::write_png(dir.file("big.png"), pattern(20, 10, 3), &error));
  CHECK_FALSE(pfx::app::read_png(dir.file("big.png"), &img, &error, 199));
  CHECK_THAT(error, Catch::Contains("exceeds the limit"));

  // Cut inside the pixel data.
  std::vector<char> bytes = pfx_test::read_bytes(dir.file("big.png"));
  bytes.resize(bytes.size() - 20);
  pfx_test::write_bytes(dir.file("cut.png"), bytes);
  CHECK_FALSE(pfx::app::read_png(dir.file("cut.png"), &img, &error));
  CHECK_THAT(error, Catch::Contains("cut.png"));
  CHECK(img.pixels.empty());
}

TEST_CASE("PNG write refuses inconsistent pixel data", "[image][png]") {
  pfx_test::TempDir dir;
  DisplayImage bad = pattern(4, 4, 3);
  bad.pixels.pop_back();
  std::string error;
  CHECK_FALSE(pfx::app::write_png(dir.file("bad.png"), bad, &error));
  CHECK_THAT(error, Catch::Contains("bad.png"));
  CHECK(dir.entries().empty());
}
