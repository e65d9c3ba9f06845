#include "obs_pictures.hpp"

#include <cstdlib>

#include <catch2/catch.hpp>

#include "png_io.hpp"
#include "render_process.hpp"

namespace pfx::test {

app::DisplayImage read_picture(const std::string& path) {
  app::DisplayImage image;
  std::string error;
  INFO(error);
  REQUIRE(app::read_png(path, &image, &error));
  if (image.channels == 4) return image;
  app::DisplayImage rgba{image.width, image.height, 4, {}};
  for (size_t i = 0; i < image.pixels.size(); i += 3) {
    rgba.pixels.insert(rgba.pixels.end(), image.pixels.begin() + i, image.pixels.begin() + i + 3);
    rgba.pixels.push_back(255);
  }
  return rgba;
}

app::DisplayImage write_photo_crop(const std::string& path, int x, int y, int width, int height, bool alpha,
                                   const std::string& photograph) {
  const app::DisplayImage photo = read_picture(photograph);
  REQUIRE(x + width <= photo.width);
  REQUIRE(y + height <= photo.height);
  app::DisplayImage crop{width, height, alpha ? 4 : 3, {}};
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const uint8_t* pixel = &photo.pixels[(size_t(y + row) * photo.width + size_t(x + column)) * 4];
      crop.pixels.insert(crop.pixels.end(), pixel, pixel + 3);
      if (alpha) crop.pixels.push_back(static_cast<uint8_t>(255 - 255 * column / (width - 1)));
    }
  std::string error;
  INFO(error);
  REQUIRE(app::write_png(path, crop, &error));
  return read_picture(path);
}

int worst_difference(const ObsFrame& frame, const app::DisplayImage& picture, bool with_alpha) {
  REQUIRE(frame.width == uint32_t(picture.width));
  REQUIRE(frame.height == uint32_t(picture.height));
  REQUIRE(picture.channels == 4);
  int worst = 0;
  for (size_t i = 0; i < frame.rgba.size(); ++i)
    if (with_alpha || i % 4 != 3) worst = std::max(worst, std::abs(int(frame.rgba[i]) - int(picture.pixels[i])));
  return worst;
}

int worst_difference_pictures(const app::DisplayImage& a, const app::DisplayImage& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.pixels.size() == b.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return worst;
}

app::DisplayImage pfx_render_picture(const std::string& input, const std::string& chain,
                                     const std::vector<std::string>& sets,
                                     const std::string& output) {
  std::string args = "--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + input + " --chain " + chain;
  for (const auto& set : sets) args += " --set '" + set + "'";
  const Result result = pfx_render(args + " --out " + output, false);
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  return read_picture(output);
}

}  // namespace pfx::test
