// Files whose data window differs from the display window, and other layouts pfx never writes
// itself, made here with the OpenEXR API.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfPartType.h>
#include <ImfOutputPart.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>

#include "exr_io.hpp"
#include "test_files.hpp"

using pfx::app::Image;

namespace {

// Distinct, exactly representable (in float) values that encode the absolute EXR coordinate.
float red_at(int x, int y) { return 1000.0f + x * 10.0f + y * 0.25f; }
float green_at(int x, int y) { return -static_cast<float>(x) + 0.5f * y; }
float blue_at(int x, int y) { return static_cast<float>(x * y); }
float depth_at(int x, int y) { return 2.0f + x + 100.0f * y; }

struct Planes {
  std::vector<float> r, g, b, z;
};

// R, G, B and Z as float over `data`, with the given display window; no A channel, so the
// reader must supply alpha 1 inside the data window.
void write_windowed(const std::string& path, const Imath::Box2i& display,
                    const Imath::Box2i& data, bool tiled = false) {
  Imf::Header header(display, data);
  for (const char* name : {"R", "G", "B", "Z"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  const int w = data.max.x - data.min.x + 1, h = data.max.y - data.min.y + 1;
  Planes p;
  for (std::vector<float>* v : {&p.r, &p.g, &p.b, &p.z}) v->resize(static_cast<std::size_t>(w) * h);
  for (int y = data.min.y; y <= data.max.y; ++y) {
    for (int x = data.min.x; x <= data.max.x; ++x) {
      const std::size_t i = static_cast<std::size_t>(y - data.min.y) * w + (x - data.min.x);
      p.r[i] = red_at(x, y);
      p.g[i] = green_at(x, y);
      p.b[i] = blue_at(x, y);
      p.z[i] = depth_at(x, y);
    }
  }
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice::Make(Imf::FLOAT, p.r.data(), data));
  fb.insert("G", Imf::Slice::Make(Imf::FLOAT, p.g.data(), data));
  fb.insert("B", Imf::Slice::Make(Imf::FLOAT, p.b.data(), data));
  fb.insert("Z", Imf::Slice::Make(Imf::FLOAT, p.z.data(), data));
  if (tiled) {
    header.setTileDescription(Imf::TileDescription(4, 3, Imf::ONE_LEVEL));
    Imf::TiledOutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  } else {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(h);
  }
}

// Checks every output pixel: inside the data window the file's values, elsewhere the
// documented "nothing there" fill (rgba 0, depth +inf).
void check_placement(const Image& img, const Imath::Box2i& display, const Imath::Box2i& data) {
  REQUIRE(img.width == display.max.x - display.min.x + 1);
  REQUIRE(img.height == display.max.y - display.min.y + 1);
  REQUIRE(img.has_depth());
  int covered = 0;
  for (int row = 0; row < img.height; ++row) {
    for (int col = 0; col < img.width; ++col) {
      const int x = display.min.x + col, y = display.min.y + row;
      const std::size_t i = static_cast<std::size_t>(row) * img.width + col;
      const float* px = &img.rgba[i * 4];
      INFO("output pixel (" << col << ", " << row << "), file pixel (" << x << ", " << y << ")");
      if (data.intersects(Imath::V2i(x, y))) {
        ++covered;
        CHECK(px[0] == red_at(x, y));
        CHECK(px[1] == green_at(x, y));
        CHECK(px[2] == blue_at(x, y));
        CHECK(px[3] == 1.0f);
        CHECK(img.depth[i] == depth_at(x, y));
      } else {
        CHECK(px[0] == 0.0f);
        CHECK(px[1] == 0.0f);
        CHECK(px[2] == 0.0f);
        CHECK(px[3] == 0.0f);
        CHECK(img.depth[i] == std::numeric_limits<float>::infinity());
      }
    }
  }
  UNSCOPED_INFO("pixels covered by the data window: " << covered);
}

void round_trip(const Imath::Box2i& display, const Imath::Box2i& data, bool tiled = false) {
  pfx_test::TempDir dir;
  const std::string path = dir.file("windowed.exr");
  write_windowed(path, display, data, tiled);
  Image img;
  std::string error;
  REQUIRE(pfx::app::read_exr(path, &img, &error));
  check_placement(img, display, data);
}

using Box = Imath::Box2i;
using V2 = Imath::V2i;

}  // namespace

TEST_CASE("EXR data window smaller than and offset inside the display window", "[image][exr]") {
  round_trip(Box(V2(0, 0), V2(15, 11)), Box(V2(3, 2), V2(9, 7)));
}

TEST_CASE("EXR data window offset to the bottom-right corner", "[image][exr]") {
  round_trip(Box(V2(0, 0), V2(12, 9)), Box(V2(8, 6), V2(12, 9)));
}

TEST_CASE("EXR display window with a negative origin", "[image][exr]") {
  round_trip(Box(V2(-4, -3), V2(10, 8)), Box(V2(-4, -3), V2(10, 8)));
  round_trip(Box(V2(-4, -3), V2(10, 8)), Box(V2(-2, 0), V2(3, 8)));
}

TEST_CASE("EXR data window reaching outside the display window is cropped", "[image][exr]") {
  round_trip(Box(V2(0, 0), V2(9, 9)), Box(V2(-3, 5), V2(5, 14)));
  round_trip(Box(V2(0, 0), V2(9, 9)), Box(V2(-5, -5), V2(14, 14)));
}

TEST_CASE("EXR data window entirely outside the display window gives an empty frame",
          "[image][exr]") {
  round_trip(Box(V2(0, 0), V2(6, 4)), Box(V2(20, 20), V2(25, 22)));
}

TEST_CASE("EXR tiled file with an offset data window", "[image][exr]") {
  round_trip(Box(V2(0, 0), V2(15, 11)), Box(V2(1, 2), V2(14, 10)), true);
}

TEST_CASE("EXR data window taller than one decoding strip", "[image][exr]") {
  // The reader decodes 256 rows at a time; this crosses two strip boundaries off the origin.
  round_trip(Box(V2(0, -10), V2(2, 600)), Box(V2(1, -5), V2(2, 590)));
}

TEST_CASE("EXR luminance-only file reads as grey", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("grey.exr");
  Imf::Header header(3, 2);
  header.channels().insert("Y", Imf::Channel(Imf::HALF));
  std::vector<half> y = {half(0.0f), half(0.25f), half(1.0f), half(2.0f), half(8.0f), half(-1.0f)};
  Imf::FrameBuffer fb;
  fb.insert("Y", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(y.data()), sizeof(half),
                            3 * sizeof(half)));
  {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(2);
  }
  Image img;
  std::string error;
  REQUIRE(pfx::app::read_exr(path, &img, &error));
  REQUIRE(img.width == 3);
  REQUIRE(img.height == 2);
  CHECK_FALSE(img.has_depth());
  for (std::size_t i = 0; i < 6; ++i) {
    const float v = static_cast<float>(y[i]);
    CHECK(img.rgba[i * 4 + 0] == v);
    CHECK(img.rgba[i * 4 + 1] == v);
    CHECK(img.rgba[i * 4 + 2] == v);
    CHECK(img.rgba[i * 4 + 3] == 1.0f);
  }
}

TEST_CASE("EXR with uint channels reads as float", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("uint.exr");
  Imf::Header header(2, 1);
  for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::UINT));
  std::vector<unsigned> v = {1, 2, 3, 40000, 50000, 60000};
  const std::size_t xs = 3 * sizeof(unsigned);
  Imf::FrameBuffer fb;
  for (int c = 0; c < 3; ++c) {
    fb.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
              Imf::Slice(Imf::UINT, reinterpret_cast<char*>(v.data() + c), xs, xs * 2));
  }
  {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(1);
  }
  Image img;
  std::string error;
  REQUIRE(pfx::app::read_exr(path, &img, &error));
  CHECK(img.rgba == std::vector<float>{1, 2, 3, 1, 40000, 50000, 60000, 1});
}

TEST_CASE("EXR without colour channels is refused with the channel list", "[image][exr]") {
  // Two channels that are no colour: nothing to show (a single one would be shown as grey).
  pfx_test::TempDir dir;
  const std::string path = dir.file("nocolour.exr");
  Imf::Header header(2, 2);
  header.channels().insert("normal.x", Imf::Channel(Imf::HALF));
  header.channels().insert("normal.y", Imf::Channel(Imf::HALF));
  std::vector<half> v(4, half(0.5f));
  Imf::FrameBuffer fb;
  for (const char* name : {"normal.x", "normal.y"}) {
    fb.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(v.data()), sizeof(half), 2 * sizeof(half)));
  }
  {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(2);
  }
  Image img;
  std::string error;
  CHECK_FALSE(pfx::app::read_exr(path, &img, &error));
  CHECK_THAT(error, Catch::Contains(path));
  CHECK_THAT(error, Catch::Contains("normal.x, normal.y"));
}

TEST_CASE("EXR multi-part file gives its first part", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("parts.exr");
  std::vector<Imf::Header> headers;
  for (int p = 0; p < 2; ++p) {
    Imf::Header h(4, 3);  // parts must share the display window
    h.setName(p == 0 ? "beauty" : "other");
    h.setType(Imf::SCANLINEIMAGE);
    for (const char* name : {"R", "G", "B"}) h.channels().insert(name, Imf::Channel(Imf::FLOAT));
    headers.push_back(h);
  }
  std::vector<float> first(4 * 3 * 3), second(4 * 3 * 3, -1.0f);
  for (std::size_t i = 0; i < first.size(); ++i) first[i] = static_cast<float>(i);
  {
    Imf::MultiPartOutputFile file(path.c_str(), headers.data(), 2);
    for (int p = 0; p < 2; ++p) {
      float* px = p == 0 ? first.data() : second.data();
      Imf::FrameBuffer fb;
      for (int c = 0; c < 3; ++c) {
        fb.insert(std::string(1, "RGB"[c]),
                  Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(px + c), 12, 12 * 4));
      }
      Imf::OutputPart part(file, p);
      part.setFrameBuffer(fb);
      part.writePixels(3);
    }
  }
  Image img;
  std::string error;
  REQUIRE(pfx::app::read_exr(path, &img, &error));
  REQUIRE(img.width == 4);
  REQUIRE(img.height == 3);
  for (std::size_t i = 0; i < 12; ++i) {
    CHECK(img.rgba[i * 4 + 0] == first[i * 3 + 0]);
    CHECK(img.rgba[i * 4 + 2] == first[i * 3 + 2]);
    CHECK(img.rgba[i * 4 + 3] == 1.0f);
  }
}
