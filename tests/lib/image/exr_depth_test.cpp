// Depth files as users have them (--depth): which channel becomes the depth, in the documented
// order, and what is refused. Files are written with OpenEXR's API; the depth read is compared with
// the values written.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "exr_channel_writer.hpp"
#include "exr_io.hpp"
#include "test_files.hpp"

using pfx_test::ExrChannel;
using pfx_test::ExrPart;

namespace {

constexpr int kW = 3, kH = 2;

std::vector<float> ramp(float base) {
  std::vector<float> v;
  for (int i = 0; i < kW * kH; ++i) v.push_back(base + 0.5f * static_cast<float>(i));
  return v;
}

struct Read {
  bool ok = false;
  pfx::app::Image image;
  std::string error, used;
};

Read read_depth(const std::string& path) {
  Read r;
  pfx::app::ExrRequest request;
  request.role = pfx::app::ExrRequest::Role::Depth;
  r.ok = pfx::app::read_exr(path, &r.image, &r.error, request, &r.used);
  return r;
}

// Writes `channels` (each holding ramp(its index)) and says which index became the depth.
struct Case {
  const char* what;
  std::vector<std::string> channels;
  std::string expected;  // the channel that must be the depth
};

}  // namespace

TEST_CASE("EXR depth: the channel taken follows Z, depth, a layer's Z, R, Y, a lone channel", "[image][exr][depth]") {
  const std::vector<Case> cases = {
      {"Z only", {"Z"}, "Z"},
      {"Z before everything", {"B", "G", "R", "Y", "Z", "depth"}, "Z"},
      {"a 'depth' channel", {"R", "depth"}, "depth"},
      {"any case", {"G", "Depth"}, "Depth"},
      {"the Z of a depth layer, not a normal's", {"ViewLayer.Depth.Z", "ViewLayer.Normal.X", "ViewLayer.Normal.Y",
                                                   "ViewLayer.Normal.Z", "ViewLayer.Combined.R"}, "ViewLayer.Depth.Z"},
      {"the Z of another layer", {"R", "G", "B", "zpass.Z"}, "zpass.Z"},
      {"a vector's Z is no depth", {"P.X", "P.Y", "P.Z", "R"}, "R"},
      {"R only", {"R"}, "R"},
      {"R before Y", {"R", "G", "B", "Y"}, "R"},
      {"Y only", {"Y"}, "Y"},
      {"Y with chroma", {"BY", "RY", "Y"}, "Y"},
      {"G only", {"G"}, "G"},
      {"a lone channel of any name", {"distance"}, "distance"},
  };
  pfx_test::TempDir dir;
  for (const Case& c : cases) {
    INFO(c.what);
    const std::string path = dir.file("depth.exr");
    std::vector<ExrChannel> channels;
    std::size_t expected_index = 0;
    for (std::size_t i = 0; i < c.channels.size(); ++i) {
      channels.push_back({c.channels[i], ramp(10.0f * static_cast<float>(i + 1)), Imf::FLOAT});
      if (c.channels[i] == c.expected) expected_index = i;
    }
    pfx_test::write_exr_channels(path, kW, kH, channels);
    const Read r = read_depth(path);
    INFO(r.error);
    REQUIRE(r.ok);
    CHECK(r.used == "depth " + c.expected);
    CHECK(r.image.depth == ramp(10.0f * static_cast<float>(expected_index + 1)));
    CHECK(r.image.rgba.empty());
    CHECK(r.image.width == kW);
  }
}

TEST_CASE("EXR depth: half and uint depth read as the values written, tiled too", "[image][exr][depth]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("typed.exr");
  for (Imf::PixelType type : {Imf::HALF, Imf::UINT}) {
    const std::vector<float> v = {1, 2, 3, 500, 1000, 2048};
    pfx_test::write_exr_channels(path, kW, kH, {{"Z", v, type}}, type == Imf::UINT);
    const Read r = read_depth(path);
    REQUIRE(r.ok);
    CHECK(r.image.depth == v);
  }
}

TEST_CASE("EXR depth: a depth part of a multi-part file is found and named", "[image][exr][depth]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("parts.exr");
  pfx_test::write_exr_parts(path, kW, kH,
                            {ExrPart{"beauty", {{"R", ramp(1.0f)}, {"G", ramp(1.0f)}, {"B", ramp(1.0f)}}, false},
                             ExrPart{"zdepth", {{"zdepth.Z", ramp(40.0f)}}, false}});
  const Read r = read_depth(path);
  INFO(r.error);
  REQUIRE(r.ok);
  CHECK(r.used == "depth zdepth.Z of part 'zdepth'");
  CHECK(r.image.depth == ramp(40.0f));
}

TEST_CASE("EXR depth: a file with no candidate is refused, naming it and listing its channels", "[image][exr][depth]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("uv.exr");
  pfx_test::write_exr_channels(path, kW, kH, {{"u", ramp(0.0f)}, {"v", ramp(0.0f)}});
  const Read r = read_depth(path);
  REQUIRE_FALSE(r.ok);
  CHECK_THAT(r.error, Catch::StartsWith(path + ": no depth channel"));
  CHECK_THAT(r.error, Catch::Contains("channels u, v"));
}
