// Texture files (tests/programs/import/models, written by make_textured_models.cpp from known swatches):
// each format decodes to the swatch's codes (exactly for the lossless ones), the format comes
// from the bytes, and broken, missing, foreign or oversized files are refused with a reason.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "texture_file.hpp"

using namespace pfx::app;

namespace {

const std::string kModels = PFX_TEST_MODELS;

// The swatch at texel (x, y): its colour +8 on one checker square of 4 texels, -8 on the other.
int swatch_code(int code, int x, int y) { return code + (((x / 4 + y / 4) % 2) ? 8 : -8); }

void check_swatch(const DisplayImage& img, int r, int g, int b, int tolerance) {
  REQUIRE(img.width == 32);
  REQUIRE(img.height == 32);
  REQUIRE(img.is_consistent());
  int worst = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const uint8_t* p = &img.pixels[(static_cast<size_t>(y) * 32 + x) * img.channels];
      const int want[3] = {swatch_code(r, x, y), swatch_code(g, x, y), swatch_code(b, x, y)};
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p[c] - want[c]));
    }
  CHECK(worst <= tolerance);
}

DisplayImage read(const std::string& relative) {
  DisplayImage img;
  std::string problem;
  INFO(relative);
  const bool ok = read_texture_file(kModels + "/" + relative, &img, &problem);
  INFO(problem);
  REQUIRE(ok);
  return img;
}

std::string refusal(const std::string& path, std::int64_t max_pixels = kMaxTexturePixels) {
  DisplayImage img;
  std::string problem;
  CHECK_FALSE(read_texture_file(path, &img, &problem, max_pixels));
  CHECK(img.width == 0);  // untouched
  return problem;
}

}  // namespace

TEST_CASE("texture files: TGA (RLE), BMP and PNG decode to their exact codes, JPEG within its loss",
          "[image][texture]") {
  check_swatch(read("tinyobj_style/blue.tga"), 50, 80, 200, 0);
  check_swatch(read("tinyobj_style/purple.bmp"), 150, 60, 170, 0);
  check_swatch(read("tinyobj_style/yellow.png"), 210, 190, 50, 0);
  // Quality 95 with 4:2:0 chroma: the sharp checker's edges move a few codes.
  check_swatch(read("assimp_style/textures/brick_red.jpg"), 190, 60, 40, 40);
  const DisplayImage grey = read("assimp_style/textures/lamp_glow.jpg");  // a one-channel JPEG
  CHECK(grey.channels == 3);
  CHECK(grey.pixels[0] == grey.pixels[1]);
}

TEST_CASE("texture files: the format comes from the bytes, not the name", "[image][texture]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("pfx-texture-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kModels + "/tinyobj_style/yellow.png", dir / "really_a_png.jpg");
  std::filesystem::copy_file(kModels + "/tinyobj_style/purple.bmp", dir / "really_a_bmp.tga");
  DisplayImage png, bmp;
  std::string problem;
  CHECK(read_texture_file((dir / "really_a_png.jpg").string(), &png, &problem));
  CHECK(read_texture_file((dir / "really_a_bmp.tga").string(), &bmp, &problem));
  std::filesystem::remove_all(dir);
  check_swatch(png, 210, 190, 50, 0);
  check_swatch(bmp, 150, 60, 170, 0);
}

TEST_CASE("texture files: truncated, corrupt, missing, foreign and oversized files are refused with a reason",
          "[image][texture][hard]") {
  CHECK(refusal(kModels + "/broken/truncated.jpg").find("truncated JPEG") != std::string::npos);
  CHECK(refusal(kModels + "/broken/truncated.tga").find("truncated TGA") != std::string::npos);
  CHECK(refusal(kModels + "/broken/corrupt.jpg").find("damaged JPEG") != std::string::npos);
  CHECK(refusal(kModels + "/nothing_here.jpg").find("no such file") != std::string::npos);
  CHECK(refusal(kModels + "/assimp_style/crates.obj").find("not a PNG, JPEG, TGA or BMP file") != std::string::npos);
  CHECK(refusal(kModels).find("is a folder") != std::string::npos);
  // 32 x 32 = 1024 pixels against a limit of 1000, for every format.
  for (const char* file : {"tinyobj_style/blue.tga", "tinyobj_style/purple.bmp", "tinyobj_style/yellow.png",
                           "assimp_style/textures/brick_red.jpg"}) {
    INFO(file);
    CHECK(refusal(kModels + "/" + file, 1000).find("exceeds the limit of 1000 pixels") != std::string::npos);
  }
  // The reason names the file.
  CHECK(refusal(kModels + "/broken/truncated.tga").rfind(kModels + "/broken/truncated.tga: ", 0) == 0);
}
