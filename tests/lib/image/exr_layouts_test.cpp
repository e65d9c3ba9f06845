// Channel layouts users hand over as colour (--input): lone channels, luminance, luminance/chroma,
// layers, parts, pixel types, subsampling, tiles. Each file is written with OpenEXR's API and
// what read_exr gives is checked against the values written.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <ImfRgbaFile.h>

#include "exr_channel_writer.hpp"
#include "exr_io.hpp"
#include "test_files.hpp"

using pfx::app::Image;
using pfx_test::ExrChannel;
using pfx_test::ExrPart;

namespace {

constexpr int kW = 4, kH = 3;

// Distinct values per channel and pixel, exact in half.
std::vector<float> ramp(float base, int count = kW * kH) {
  std::vector<float> v;
  for (int i = 0; i < count; ++i) v.push_back(base + 0.25f * static_cast<float>(i));
  return v;
}

struct Read {
  bool ok = false;
  Image image;
  std::string error, used;
};

Read read(const std::string& path, const std::string& layer = "") {
  Read r;
  pfx::app::ExrRequest request;
  request.layer = layer;
  r.ok = pfx::app::read_exr(path, &r.image, &r.error, request, &r.used);
  INFO(r.error);
  return r;
}

// The pixel's RGBA as read.
std::vector<float> pixel(const Image& img, int i) {
  return {img.rgba[i * 4 + 0], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2], img.rgba[i * 4 + 3]};
}

}  // namespace

TEST_CASE("EXR colour: a lone R, G or B channel stays in its place, the others 0, alpha 1", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  for (int c = 0; c < 3; ++c) {
    const std::string name(1, "RGB"[c]);
    const std::string path = dir.file(name + ".exr");
    pfx_test::write_exr_channels(path, kW, kH, {{name, ramp(1.0f), Imf::HALF}});
    const Read r = read(path);
    REQUIRE(r.ok);
    CHECK_FALSE(r.image.has_depth());
    CHECK(r.used == name + " (no " + (c == 0 ? "G, B" : c == 1 ? "R, B" : "R, G") + ": 0) (no A: alpha 1)");
    const std::vector<float> v = ramp(1.0f);
    for (int i = 0; i < kW * kH; ++i) {
      std::vector<float> want = {0, 0, 0, 1};
      want[static_cast<std::size_t>(c)] = v[static_cast<std::size_t>(i)];
      CHECK(pixel(r.image, i) == want);
    }
  }
}

TEST_CASE("EXR colour: R and B without G keep their values, G is 0", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("rb.exr");
  pfx_test::write_exr_channels(path, kW, kH, {{"R", ramp(2.0f)}, {"B", ramp(-3.0f)}, {"A", ramp(0.0f)}});
  const Read r = read(path);
  REQUIRE(r.ok);
  for (int i = 0; i < kW * kH; ++i) {
    CHECK(pixel(r.image, i) ==
          std::vector<float>{ramp(2.0f)[static_cast<std::size_t>(i)], 0.0f, ramp(-3.0f)[static_cast<std::size_t>(i)],
                             ramp(0.0f)[static_cast<std::size_t>(i)]});
  }
}

TEST_CASE("EXR colour: a lone channel that is no colour (Z, depth, A, a matte) reads as grey", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  for (const std::string name : {"Z", "depth", "A", "matte", "mask.V"}) {
    const std::string path = dir.file("lone.exr");
    pfx_test::write_exr_channels(path, kW, kH, {{name, ramp(0.5f)}});
    const Read r = read(path);
    INFO(name);
    REQUIRE(r.ok);
    CHECK(r.used.find("'" + name + "' as grey") != std::string::npos);
    for (int i = 0; i < kW * kH; ++i) {
      const float v = ramp(0.5f)[static_cast<std::size_t>(i)];
      CHECK(pixel(r.image, i) == std::vector<float>{v, v, v, name == "A" ? v : 1.0f});
    }
    // A lone Z is the depth too; nothing else is.
    CHECK(r.image.has_depth() == (name == "Z" || name == "depth"));
    if (r.image.has_depth()) CHECK(r.image.depth == ramp(0.5f));
  }
}

TEST_CASE("EXR colour: Y with A is grey with that alpha", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("ya.exr");
  pfx_test::write_exr_channels(path, kW, kH, {{"Y", ramp(1.0f), Imf::HALF}, {"A", ramp(0.0f), Imf::HALF}});
  const Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "Y as grey, A");
  for (int i = 0; i < kW * kH; ++i) {
    const float y = ramp(1.0f)[static_cast<std::size_t>(i)], a = ramp(0.0f)[static_cast<std::size_t>(i)];
    CHECK(pixel(r.image, i) == std::vector<float>{y, y, y, a});
  }
}

TEST_CASE("EXR colour: Y, RY, BY at full resolution convert back to the RGB they were made from",
          "[image][exr][layouts]") {
  // Rec. 709 luminance weights (the default chromaticities), written out so the expectation does
  // not come from the code under test.
  const float wr = 0.2126f, wg = 0.7152f, wb = 0.0722f;
  const std::vector<std::vector<float>> rgb = {{1.0f, 0.5f, 0.25f}, {0.1f, 2.0f, 0.3f}, {4.0f, 4.0f, 4.0f},
                                               {0.2f, 0.05f, 3.0f}};
  std::vector<float> y, ry, by;
  for (const auto& c : rgb) {
    const float l = wr * c[0] + wg * c[1] + wb * c[2];
    y.push_back(l);
    ry.push_back((c[0] - l) / l);
    by.push_back((c[2] - l) / l);
  }
  pfx_test::TempDir dir;
  const std::string path = dir.file("yc.exr");
  pfx_test::write_exr_channels(path, 2, 2, {{"Y", y}, {"RY", ry}, {"BY", by}});
  const Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "Y, RY, BY converted to RGB (no A: alpha 1)");
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) {
      CHECK(r.image.rgba[static_cast<std::size_t>(i * 4 + c)] ==
            Approx(rgb[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)]).epsilon(1e-3));
    }
  }
}

TEST_CASE("EXR colour: a luminance/chroma file from OpenEXR's RgbaOutputFile reads as its RGB",
          "[image][exr][layouts]") {
  // WRITE_YCA stores Y at full resolution and RY, BY subsampled 2x2: what OpenEXR's own
  // luminance/chroma images are. A smooth picture, so the chroma reconstruction matters little.
  const int w = 16, h = 12;
  std::vector<Imf::Rgba> pixels;
  for (int yy = 0; yy < h; ++yy) {
    for (int x = 0; x < w; ++x) {
      pixels.emplace_back(0.5f + 0.05f * x, 0.25f + 0.04f * yy, 1.0f - 0.03f * x, 0.75f);
    }
  }
  pfx_test::TempDir dir;
  const std::string path = dir.file("yca.exr");
  {
    Imf::RgbaOutputFile file(path.c_str(), w, h, Imf::WRITE_YCA);
    file.setFrameBuffer(pixels.data(), 1, w);
    file.writePixels(h);
  }
  // OpenEXR's own decoder of such files, as the second reference (its chroma filter is not a linear
  // one: the two differ by up to 2.5% on this picture).
  std::vector<Imf::Rgba> decoded(static_cast<std::size_t>(w * h));
  {
    Imf::RgbaInputFile file(path.c_str());
    file.setFrameBuffer(decoded.data(), 1, w);
    file.readPixels(0, h - 1);
  }
  const Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "Y, RY, BY converted to RGB, A");
  for (int i = 0; i < w * h; ++i) {
    INFO("pixel " << i % w << ", " << i / w);
    const Imf::Rgba& d = decoded[static_cast<std::size_t>(i)];
    const Imf::Rgba& p = pixels[static_cast<std::size_t>(i)];
    const float* got = r.image.rgba.data() + i * 4;
    CHECK(got[0] == Approx(float(d.r)).epsilon(0.03));
    CHECK(got[1] == Approx(float(d.g)).epsilon(0.03));
    CHECK(got[2] == Approx(float(d.b)).epsilon(0.03));
    CHECK(got[3] == float(p.a));
    // The written colours, up to half precision and chroma kept at a quarter of the samples,
    // except on the last column and row, which no chroma sample follows (OpenEXR's decoder is
    // off by some 5% there too).
    if (i % w == w - 1 || i / w == h - 1) continue;
    CHECK(got[0] == Approx(float(p.r)).epsilon(0.02));
    CHECK(got[1] == Approx(float(p.g)).epsilon(0.02));
    CHECK(got[2] == Approx(float(p.b)).epsilon(0.02));
  }
}

TEST_CASE("EXR colour: a subsampled channel is spread over its pixels by linear interpolation",
          "[image][exr][layouts]") {
  // B stored at every second pixel in x and y: samples at (0,0) (2,0) (0,2) (2,2) of a 4x4 image.
  const std::vector<float> b = {0.0f, 8.0f, 4.0f, 12.0f};
  pfx_test::TempDir dir;
  const std::string path = dir.file("sub.exr");
  pfx_test::write_exr_channels(path, 4, 4,
                               {{"R", ramp(0.0f, 16)}, {"G", ramp(1.0f, 16)}, {"B", b, Imf::FLOAT, 2, 2}});
  const Read r = read(path);
  REQUIRE(r.ok);
  auto blue = [&](int x, int y) { return r.image.rgba[static_cast<std::size_t>((y * 4 + x) * 4 + 2)]; };
  CHECK(blue(0, 0) == 0.0f);   // on samples: as stored
  CHECK(blue(2, 0) == 8.0f);
  CHECK(blue(0, 2) == 4.0f);
  CHECK(blue(2, 2) == 12.0f);
  CHECK(blue(1, 0) == 4.0f);   // halfway between (0,0) and (2,0)
  CHECK(blue(0, 1) == 2.0f);   // halfway between (0,0) and (0,2)
  CHECK(blue(1, 1) == 6.0f);   // the four samples' mean
  CHECK(blue(3, 3) == 12.0f);  // past the last sample: the last sample
  CHECK(r.image.rgba[(5 * 4) + 0] == ramp(0.0f, 16)[5]);  // full-resolution channels untouched
}

TEST_CASE("EXR colour: half, float and uint channels read as the values written", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::vector<float> whole = {0, 1, 7, 255, 65535, 1 << 20, 3, 9, 12, 100000, 16777216, 42};
  for (Imf::PixelType type : {Imf::HALF, Imf::FLOAT, Imf::UINT}) {
    const std::string path = dir.file("types.exr");
    const std::vector<float> v = type == Imf::UINT ? whole : ramp(-1.0f);
    pfx_test::write_exr_channels(path, kW, kH, {{"G", v, type}});
    const Read r = read(path);
    REQUIRE(r.ok);
    for (int i = 0; i < kW * kH; ++i) CHECK(r.image.rgba[i * 4 + 1] == v[static_cast<std::size_t>(i)]);
  }
}

TEST_CASE("EXR colour: a tiled file with one channel reads like a scanline one", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("tiled.exr");
  const int w = 9, h = 7;  // not a multiple of the 4x4 tiles
  pfx_test::write_exr_channels(path, w, h, {{"Y", ramp(0.0f, w * h), Imf::HALF}}, true);
  const Read r = read(path);
  REQUIRE(r.ok);
  REQUIRE(r.image.width == w);
  for (int i = 0; i < w * h; ++i) CHECK(r.image.rgba[i * 4 + 2] == ramp(0.0f, w * h)[static_cast<std::size_t>(i)]);
}

TEST_CASE("EXR colour: the one layer with colour is taken when no colour channel is plain", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("layer.exr");
  // N.X, N.Y, N.Z are a normal's axes, not luminance and depth; depth.Z is the depth.
  pfx_test::write_exr_channels(path, kW, kH,
                               {{"N.X", ramp(9.0f)}, {"N.Y", ramp(9.0f)}, {"N.Z", ramp(9.0f)},
                                {"diffuse.R", ramp(1.0f)}, {"diffuse.G", ramp(2.0f)}, {"diffuse.B", ramp(3.0f)},
                                {"diffuse.A", ramp(0.0f)}, {"depth.Z", ramp(5.0f)}});
  const Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "layer 'diffuse': R, G, B, A; depth depth.Z");
  for (int i = 0; i < kW * kH; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    CHECK(pixel(r.image, i) == std::vector<float>{ramp(1.0f)[k], ramp(2.0f)[k], ramp(3.0f)[k], ramp(0.0f)[k]});
  }
  CHECK(r.image.depth == ramp(5.0f));
}

TEST_CASE("EXR colour: plain R, G, B win over layers", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("plain.exr");
  pfx_test::write_exr_channels(path, kW, kH,
                               {{"R", ramp(1.0f)}, {"G", ramp(2.0f)}, {"B", ramp(3.0f)}, {"spec.R", ramp(7.0f)},
                                {"spec.G", ramp(7.0f)}, {"spec.B", ramp(7.0f)}});
  const Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "R, G, B (no A: alpha 1)");
  CHECK(r.image.rgba[0] == 1.0f);
}

TEST_CASE("EXR colour: several layers are refused with their names, and --layer picks one", "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("layers.exr");
  pfx_test::write_exr_channels(path, kW, kH,
                               {{"diffuse.R", ramp(1.0f)}, {"diffuse.G", ramp(1.0f)}, {"diffuse.B", ramp(1.0f)},
                                {"specular.R", ramp(4.0f)}, {"specular.G", ramp(5.0f)}, {"specular.B", ramp(6.0f)}});
  Read r = read(path);
  REQUIRE_FALSE(r.ok);
  CHECK_THAT(r.error, Catch::StartsWith(path + ": "));
  CHECK_THAT(r.error, Catch::Contains("diffuse, specular"));
  CHECK_THAT(r.error, Catch::Contains("--layer"));

  r = read(path, "specular");
  REQUIRE(r.ok);
  CHECK(r.used == "layer 'specular': R, G, B (no A: alpha 1)");
  CHECK(pixel(r.image, 2) == std::vector<float>{4.5f, 5.5f, 6.5f, 1.0f});

  r = read(path, "glossy");
  REQUIRE_FALSE(r.ok);
  CHECK_THAT(r.error, Catch::Contains("no part or layer named 'glossy'"));
  CHECK_THAT(r.error, Catch::Contains("diffuse, specular"));
}

TEST_CASE("EXR colour: channels with nothing to show are refused, naming the file and listing them",
          "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("uv.exr");
  pfx_test::write_exr_channels(path, kW, kH, {{"u", ramp(0.0f)}, {"v", ramp(0.0f)}});
  const Read r = read(path);
  REQUIRE_FALSE(r.ok);
  CHECK_THAT(r.error, Catch::StartsWith(path + ": "));
  CHECK_THAT(r.error, Catch::Contains("u, v"));
}

TEST_CASE("EXR colour: --layer names a part of a multi-part file, and without it the first part is read",
          "[image][exr][layouts]") {
  pfx_test::TempDir dir;
  const std::string path = dir.file("parts.exr");
  pfx_test::write_exr_parts(path, kW, kH,
                            {ExrPart{"beauty", {{"R", ramp(1.0f)}, {"G", ramp(1.0f)}, {"B", ramp(1.0f)}}, false},
                             ExrPart{"diffuse", {{"diffuse.R", ramp(3.0f)}, {"diffuse.G", ramp(3.0f)},
                                                 {"diffuse.B", ramp(3.0f)}}, true},
                             ExrPart{"depth", {{"Z", ramp(8.0f)}}, false}});
  Read r = read(path);
  REQUIRE(r.ok);
  CHECK(r.used == "part 'beauty', R, G, B (no A: alpha 1)");
  CHECK(r.image.rgba[0] == 1.0f);
  r = read(path, "diffuse");  // a tiled part whose channels carry the layer name
  REQUIRE(r.ok);
  CHECK(r.used == "part 'diffuse', layer 'diffuse': R, G, B (no A: alpha 1)");
  CHECK(r.image.rgba[4] == 3.25f);
  r = read(path, "depth");
  REQUIRE(r.ok);
  CHECK(r.image.rgba[4] == 8.25f);
  CHECK(r.image.depth == ramp(8.0f));
}
