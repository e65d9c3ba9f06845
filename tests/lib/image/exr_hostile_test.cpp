// Files that are missing, not EXR, damaged or lying about their size. Each must give a clear
// error naming the file, never a crash and never a huge allocation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfTileDescription.h>
#include <ImfTiledOutputFile.h>

#include "exr_io.hpp"
#include "test_files.hpp"

using pfx::app::ExrPixelType;
using pfx::app::Image;

namespace {

Image small_image() {
  Image img;
  img.width = 37;
  img.height = 19;
  img.rgba.resize(img.pixel_count() * 4);
  img.depth.resize(img.pixel_count());
  for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = 0.01f * static_cast<float>(i % 97);
  for (std::size_t i = 0; i < img.depth.size(); ++i) img.depth[i] = 1.0f + i;
  return img;
}

std::vector<char> valid_exr_bytes(const pfx_test::TempDir& dir) {
  const std::string path = dir.file("valid.exr");
  std::string error;
  REQUIRE(pfx::app::write_exr(path, small_image(), ExrPixelType::Half, &error));
  return pfx_test::read_bytes(path);
}

// Offset of the value of the named box2i attribute ("dataWindow", "displayWindow").
std::size_t box_attribute_value(const std::vector<char>& bytes, const std::string& name) {
  const std::string key = name + std::string(1, '\0') + "box2i" + std::string(1, '\0');
  const auto it = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  REQUIRE(it != bytes.end());
  return static_cast<std::size_t>(it - bytes.begin()) + key.size() + 4;  // skip the size field
}

// The header ends with a zero byte before the offset table; everything before that is the
// part of the file the parser trusts most.
std::size_t header_length(const std::vector<char>& bytes) {
  const std::size_t after_data_window = box_attribute_value(bytes, "dataWindow") + 16;
  // Attributes are sorted by name when written, so a couple more follow; search for the
  // terminating empty name conservatively from the last known one.
  const std::string last = std::string("screenWindowWidth") + '\0' + "float" + '\0';
  const auto it = std::search(bytes.begin(), bytes.end(), last.begin(), last.end());
  const std::size_t end = it == bytes.end() ? after_data_window
                                            : static_cast<std::size_t>(it - bytes.begin()) +
                                                  last.size() + 4 + 4 + 1;
  return std::min(end, bytes.size());
}

void put_int32(std::vector<char>& bytes, std::size_t at, std::int32_t v) {
  const std::uint32_t u = static_cast<std::uint32_t>(v);
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((u >> (8 * i)) & 0xff);
}

// This process's peak resident memory in bytes since the last reset_peak_resident() (VmHWM).
std::uint64_t peak_resident_bytes() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;
  return 0;
}
void reset_peak_resident() { std::ofstream("/proc/self/clear_refs") << "5"; }

void expect_refused(const std::string& path, const std::string& reason_part) {
  Image img;
  img.width = 123;  // read_exr must leave *out alone on failure
  std::string error;
  CHECK_FALSE(pfx::app::read_exr(path, &img, &error));
  CHECK_THAT(error, Catch::Contains(path));
  CHECK_THAT(error, Catch::Contains(reason_part));
  CHECK(img.width == 123);
}

}  // namespace

TEST_CASE("EXR read of a missing file names it", "[image][exr]") {
  pfx_test::TempDir dir;
  expect_refused(dir.file("does-not-exist.exr"), "no such file");
}

TEST_CASE("EXR read of a folder says so", "[image][exr]") {
  pfx_test::TempDir dir;
  expect_refused(dir.path(), "folder");
}

TEST_CASE("EXR read of an empty file says it is empty", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("empty.exr");
  pfx_test::write_text(path, "");
  expect_refused(path, "empty");
}

TEST_CASE("EXR read of a text file says it is not an EXR", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("notes.exr");
  pfx_test::write_text(path, "this is not an image\nat all\n");
  expect_refused(path, "not an OpenEXR file");
}

TEST_CASE("EXR read of the magic number followed by garbage fails cleanly", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("garbage.exr");
  std::vector<char> bytes = {0x76, 0x2f, 0x31, 0x01};
  std::uint32_t state = 12345;  // fixed-seed LCG: the same garbage every run
  for (int i = 0; i < 4096; ++i) {
    state = state * 1664525u + 1013904223u;
    bytes.push_back(static_cast<char>(state >> 24));
  }
  pfx_test::write_bytes(path, bytes);
  expect_refused(path, "garbage.exr");
}

TEST_CASE("EXR truncated at any length is refused without crashing", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::vector<char> bytes = valid_exr_bytes(dir);
  REQUIRE(bytes.size() > 100);
  const std::string path = dir.file("truncated.exr");
  int refused = 0;
  for (std::size_t len = 1; len < bytes.size(); ++len) {
    pfx_test::write_bytes(path, std::vector<char>(bytes.begin(), bytes.begin() + len));
    Image img;
    std::string error;
    INFO("cut at " << len << " of " << bytes.size() << " bytes");
    const bool ok = pfx::app::read_exr(path, &img, &error);
    CHECK_FALSE(ok);
    if (!ok) {
      ++refused;
      CHECK_THAT(error, Catch::Contains(path));
    }
  }
  CHECK(refused == static_cast<int>(bytes.size()) - 1);
}

TEST_CASE("EXR with any header byte flipped never crashes and names the file", "[image][exr]") {
  pfx_test::TempDir dir;
  const std::vector<char> bytes = valid_exr_bytes(dir);
  const std::size_t header_end = header_length(bytes);
  REQUIRE(header_end > 50);
  const std::string path = dir.file("flipped.exr");
  int refused = 0;
  for (std::size_t at = 0; at < header_end; ++at) {
    for (const unsigned char mask : {0xffu, 0x01u, 0x80u}) {
      std::vector<char> damaged = bytes;
      damaged[at] = static_cast<char>(static_cast<unsigned char>(damaged[at]) ^ mask);
      pfx_test::write_bytes(path, damaged);
      Image img;
      std::string error;
      INFO("byte " << at << " xor " << int(mask));
      // Some bytes are harmless to flip (e.g. a float attribute nobody reads); the point is
      // that none of them crash and every refusal says which file.
      if (!pfx::app::read_exr(path, &img, &error)) {
        ++refused;
        CHECK_THAT(error, Catch::Contains(path));
      } else {
        CHECK(img.is_consistent());
      }
    }
  }
  CHECK(refused > 0);
  // The magic number in particular is recognised as such.
  std::vector<char> bad_magic = bytes;
  bad_magic[0] = 'X';
  pfx_test::write_bytes(path, bad_magic);
  expect_refused(path, "not an OpenEXR file");
}

TEST_CASE("EXR header declaring a 2^30 x 2^30 image is refused before allocating",
          "[image][exr]") {
  pfx_test::TempDir dir;
  const std::vector<char> bytes = valid_exr_bytes(dir);
  const std::int32_t huge = (1 << 30) - 1;

  SECTION("data and display window") {
    std::vector<char> patched = bytes;
    for (const char* name : {"dataWindow", "displayWindow"}) {
      const std::size_t at = box_attribute_value(patched, name);
      put_int32(patched, at + 8, huge);
      put_int32(patched, at + 12, huge);
    }
    const std::string path = dir.file("huge.exr");
    pfx_test::write_bytes(path, patched);
    reset_peak_resident();
    const std::uint64_t before = peak_resident_bytes();
    expect_refused(path, "exceeds the limit");
    // Refused before allocating: one row of the declared image alone is 2^30 pixels of four
    // half-floats, 8 GiB, and the peak grew by less than 1/64 of it.
    const std::uint64_t row_bytes = std::uint64_t{huge} * 4 * 2;
    INFO("peak resident memory grew by " << (peak_resident_bytes() - before) / 1024 << " KiB");
    CHECK(peak_resident_bytes() - before < row_bytes / 64);
  }
  SECTION("data window only") {
    std::vector<char> patched = bytes;
    const std::size_t at = box_attribute_value(patched, "dataWindow");
    put_int32(patched, at + 12, huge);
    const std::string path = dir.file("tall.exr");
    pfx_test::write_bytes(path, patched);
    expect_refused(path, "data window");
  }
  SECTION("display window only") {
    std::vector<char> patched = bytes;
    const std::size_t at = box_attribute_value(patched, "displayWindow");
    put_int32(patched, at + 0, -huge);
    put_int32(patched, at + 8, huge);
    const std::string path = dir.file("wide.exr");
    pfx_test::write_bytes(path, patched);
    expect_refused(path, "display window");
  }
  SECTION("inverted (empty) data window") {
    std::vector<char> patched = bytes;
    const std::size_t at = box_attribute_value(patched, "dataWindow");
    put_int32(patched, at + 8, -10);
    const std::string path = dir.file("inverted.exr");
    pfx_test::write_bytes(path, patched);
    expect_refused(path, "inverted.exr");
  }
}

TEST_CASE("EXR header attribute claiming more bytes than the file holds is refused",
          "[image][exr]") {
  // OpenEXR's C++ reader would allocate the declared 2 GiB for this string before finding the
  // file too short.
  pfx_test::TempDir dir;
  const std::vector<char> bytes = valid_exr_bytes(dir);
  const std::size_t end = header_length(bytes) - 1;  // just before the terminating empty name
  std::vector<char> attribute;
  for (const char* s : {"comments", "string"}) attribute.insert(attribute.end(), s, s + std::strlen(s) + 1);
  const std::size_t size_at = attribute.size();
  attribute.resize(size_at + 4);
  put_int32(attribute, size_at, 0x7ffffff0);
  attribute.insert(attribute.end(), {'a', 'b', 'c'});
  std::vector<char> patched(bytes.begin(), bytes.begin() + end);
  patched.insert(patched.end(), attribute.begin(), attribute.end());
  patched.insert(patched.end(), bytes.begin() + end, bytes.end());
  const std::string path = dir.file("long-comment.exr");
  pfx_test::write_bytes(path, patched);
  expect_refused(path, "attribute 'comments' declares 2147483632 bytes");
}

TEST_CASE("EXR size limits are configurable", "[image][exr]") {
  pfx_test::TempDir dir;
  valid_exr_bytes(dir);
  const std::string path = dir.file("valid.exr");
  Image img;
  std::string error;

  pfx::app::ExrLimits area;
  area.max_pixels = 100;
  CHECK_FALSE(pfx::app::read_exr(path, &img, &error, area));
  CHECK_THAT(error, Catch::Contains("exceeds the limit of 100 pixels"));

  pfx::app::ExrLimits side;
  side.max_dimension = 30;
  CHECK_FALSE(pfx::app::read_exr(path, &img, &error, side));
  CHECK_THAT(error, Catch::Contains("37x19"));

  pfx::app::ExrLimits exact;
  exact.max_dimension = 37;
  exact.max_pixels = 37 * 19;
  CHECK(pfx::app::read_exr(path, &img, &error, exact));
}

TEST_CASE("EXR tiled header declaring huge tiles is refused before OpenEXR allocates them",
          "[image][exr]") {
  // fuzz.exr found it: a 4x17039360 tile on a 9x7 image made OpenEXR allocate a row of tiles,
  // 2.4 GB, when the file was read by scanlines.
  pfx_test::TempDir dir;
  // A 9x7 float RGB image of 0.5 in tiles of tile_w x tile_h.
  auto write_tiled = [&](const std::string& path, int tile_w, int tile_h) {
    const int w = 9, h = 7;
    std::vector<float> plane(static_cast<std::size_t>(w) * h, 0.5f);
    Imf::Header header(w, h);
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    header.setTileDescription(Imf::TileDescription(tile_w, tile_h, Imf::ONE_LEVEL));
    Imf::FrameBuffer fb;
    for (const char* name : {"R", "G", "B"})
      fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.data()), sizeof(float), sizeof(float) * w));
    Imf::TiledOutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  };
  const std::string valid = dir.file("tiled.exr");
  write_tiled(valid, 4, 4);
  Image img;
  std::string error;
  REQUIRE(pfx::app::read_exr(valid, &img, &error));
  CHECK(img.rgba[0] == 0.5f);

  const std::vector<char> bytes = pfx_test::read_bytes(valid);
  const std::string key = std::string("tiles") + '\0' + "tiledesc" + '\0';
  const auto it = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  REQUIRE(it != bytes.end());
  const std::size_t at = static_cast<std::size_t>(it - bytes.begin()) + key.size() + 4;  // x size, y size
  SECTION("a row of tiles too large") {
    std::vector<char> patched = bytes;
    put_int32(patched, at + 4, 17039360);
    const std::string path = dir.file("tall-tiles.exr");
    pfx_test::write_bytes(path, patched);
    expect_refused(path, "tile size 4x17039360 exceeds the limit of 67108864 pixels");
  }
  SECTION("one tile too large") {
    std::vector<char> patched = bytes;
    put_int32(patched, at + 0, 1 << 16);
    put_int32(patched, at + 4, 1 << 16);
    const std::string path = dir.file("huge-tiles.exr");
    pfx_test::write_bytes(path, patched);
    expect_refused(path, "tile size 65536x65536 exceeds the limit");
  }
  SECTION("the limit applies to a row of tiles even when the image fits") {
    const std::string path = dir.file("tiles-4x16.exr");
    write_tiled(path, 4, 16);
    pfx::app::ExrLimits limits;
    limits.max_pixels = 143;  // the image (63 pixels) fits, a row of tiles (9x16 = 144) does not
    CHECK_FALSE(pfx::app::read_exr(path, &img, &error, limits));
    CHECK_THAT(error, Catch::Contains("tile size 4x16 exceeds the limit of 143 pixels"));
    limits.max_pixels = 144;
    CHECK(pfx::app::read_exr(path, &img, &error, limits));
    CHECK(img.rgba[0] == 0.5f);
  }
}
