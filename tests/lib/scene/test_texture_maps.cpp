// Texture files as scene maps: colour maps decoded from sRGB (IEC 61966-2-1, values computed
// here), data maps kept linear, alpha from the alpha channel or the grey level, a grey bump map
// turned into the normals of its height field, and a coloured one taken as a normal map.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "texture_maps.hpp"

using namespace pfx::app;

namespace {

DisplayImage image(int width, int height, int channels, std::vector<uint8_t> pixels) {
  DisplayImage img;
  img.width = width;
  img.height = height;
  img.channels = channels;
  img.pixels = std::move(pixels);
  return img;
}

}  // namespace

TEST_CASE("colour maps are decoded from sRGB, rows flipped to bottom first", "[scene][maps]") {
  // Top row: codes 0, 128, 255 and 10 (below the linear segment's end); bottom row 255.
  const DisplayImage img = image(2, 2, 3, {0, 128, 255, 10, 10, 10, 255, 255, 255, 255, 255, 255});
  const Texture t = make_map(img, MapKind::color);
  REQUIRE(t.rgba.size() == 16);
  // The top row is the texture's second row.
  CHECK(t.rgba[8] == 0.0f);
  CHECK(t.rgba[9] == Approx(0.21586050011389923).epsilon(1e-6));  // ((128/255 + 0.055) / 1.055)^2.4
  CHECK(t.rgba[10] == 1.0f);
  CHECK(t.rgba[11] == 1.0f);  // no alpha in the file: opaque
  CHECK(t.rgba[12] == Approx(10 / 255.0 / 12.92).epsilon(1e-6));
  CHECK(t.rgba[0] == 1.0f);
}

TEST_CASE("data maps stay linear, and alpha comes from the alpha channel or the grey level", "[scene][maps]") {
  const DisplayImage rgba = image(1, 1, 4, {128, 64, 32, 51});
  const Texture normal = make_map(rgba, MapKind::normal);
  CHECK(normal.rgba[0] == Approx(128 / 255.0));
  CHECK(normal.rgba[3] == Approx(0.2));
  CHECK(make_map(rgba, MapKind::alpha).rgba[3] == Approx(0.2));
  const DisplayImage grey = image(1, 1, 3, {204, 204, 204});
  CHECK(make_map(grey, MapKind::alpha).rgba[3] == Approx(0.8));
  CHECK(make_map(grey, MapKind::color).rgba[3] == 1.0f);
}

TEST_CASE("a grey bump map becomes the normals of its height field, a coloured one is a normal map",
          "[scene][maps]") {
  // Heights rising along U (x) by 8 codes a texel, constant along V.
  const int w = 8, h = 4;
  std::vector<uint8_t> pixels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pixels.insert(pixels.end(), 3, static_cast<uint8_t>(100 + 8 * x));
  const Texture bump = make_map(image(w, h, 3, pixels), MapKind::bump);
  // Away from the wrap-around, every normal leans against the slope (-U), not along V, and is unit.
  for (int y = 0; y < h; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const float* p = &bump.rgba[(static_cast<size_t>(y) * w + x) * 4];
      const glm::vec3 n(p[0] * 2 - 1, p[1] * 2 - 1, p[2] * 2 - 1);
      CHECK(n.x < -0.05f);
      CHECK(n.y == Approx(0.0f).margin(1e-6));
      CHECK(n.z > 0.5f);
      CHECK(glm::length(n) == Approx(1.0f).epsilon(1e-5));
      // Every texel of the ramp has the same slope, so the same normal.
      CHECK(p[0] == Approx(bump.rgba[4 + static_cast<size_t>(y) * w * 4]));
    }
  const DisplayImage coloured = image(1, 1, 3, {100, 150, 250});
  const Texture as_normal = make_map(coloured, MapKind::bump);
  CHECK(as_normal.rgba[0] == Approx(100 / 255.0));
  CHECK(as_normal.rgba[2] == Approx(250 / 255.0));
}
