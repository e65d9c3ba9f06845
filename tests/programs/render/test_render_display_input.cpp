// pfx-render with an 8-bit PNG --input (what the video-host adapters get): every code comes back
// through the transfer unchanged, the decode is the exact sRGB curve (or linear), parameters
// start from the display-referred defaults (--defaults to choose), and the options that do not
// fit an 8-bit input are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "exr_io.hpp"
#include "png_io.hpp"
#include "render_process.hpp"

using pfx::app::DisplayImage;
using pfx::test::pfx_render;
using pfx::test::Result;
using pfx::test::Scratch;

namespace {

// Every code in R (and reversed in G, scrambled in B) along x; alpha differs per row, one row
// fully transparent.
DisplayImage every_code(int channels) {
  DisplayImage image;
  image.width = 256;
  image.height = 4;
  image.channels = channels;
  const int alphas[] = {255, 128, 0, 37};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      image.pixels.push_back(static_cast<uint8_t>(x));
      image.pixels.push_back(static_cast<uint8_t>(255 - x));
      image.pixels.push_back(static_cast<uint8_t>((x * 7 + y) % 256));
      if (channels == 4) image.pixels.push_back(static_cast<uint8_t>(alphas[y]));
    }
  return image;
}

// A white square on dark grey: what blooms on an SDR frame.
DisplayImage white_square() {
  DisplayImage image;
  image.width = image.height = 48;
  image.channels = 3;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      const bool inside = x >= 20 && x < 28 && y >= 20 && y < 28;
      for (int c = 0; c < 3; ++c) image.pixels.push_back(inside ? 255 : 30);
    }
  return image;
}

std::string write(const Scratch& scratch, const std::string& name, const DisplayImage& image) {
  std::string error;
  REQUIRE(pfx::app::write_png(scratch / name, image, &error));
  return scratch / name;
}

DisplayImage read(const std::string& path) {
  DisplayImage image;
  std::string error;
  INFO(error);
  REQUIRE(pfx::app::read_png(path, &image, &error));
  return image;
}

double srgb_to_linear(double code) {
  const double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

Result bloom_render(const std::string& args) { return pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " " + args, false); }

}  // namespace

TEST_CASE("an 8-bit input with no effect comes back code for code, alpha included, for either transfer",
          "[render][display]") {
  Scratch scratch;
  for (int channels : {3, 4}) {
    const DisplayImage input = every_code(channels);
    const std::string in = write(scratch, "codes" + std::to_string(channels) + ".png", input);
    for (const char* transfer : {"srgb", "linear"}) {
      INFO(channels << " channels, " << transfer);
      Result r = pfx_render("--input " + in + " --chain '' --transfer " + transfer + " --out " + scratch / "back.png");
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      const DisplayImage back = read(scratch / "back.png");
      CHECK(back.channels == channels);
      CHECK(back.pixels == input.pixels);
    }
  }
}

TEST_CASE("an 8-bit input is decoded with the exact sRGB curve, or as linear codes, and alpha is never curved",
          "[render][display]") {
  Scratch scratch;
  const DisplayImage input = every_code(4);
  const std::string in = write(scratch, "codes.png", input);
  for (const bool srgb : {true, false}) {
    Result r = pfx_render("--input " + in + " --chain '' --transfer " + (srgb ? "srgb" : "linear") + " --out " +
                          scratch / "decoded.exr" + " --float --json");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(nlohmann::json::parse(r.out)["input"]["read"] ==
          std::string("R, G, B, A (8-bit, decoded as ") + (srgb ? "srgb" : "linear") + ")");
    pfx::app::Image decoded;
    std::string error;
    REQUIRE(pfx::app::read_exr(scratch / "decoded.exr", &decoded, &error));
    REQUIRE(decoded.width == 256);
    double worst = 0;
    for (size_t i = 0; i < input.pixels.size(); ++i) {
      const double code = input.pixels[i];
      const double expected = (i % 4 == 3 || !srgb) ? code / 255.0 : srgb_to_linear(code);
      // The chain's colour is half float: 11 significant bits.
      worst = std::max(worst, std::abs(decoded.rgba[i] - expected) / std::max(expected, 1e-3));
    }
    CHECK(worst < 1.0 / 1024);
  }
}

TEST_CASE("an 8-bit input starts from the display-referred defaults, and --defaults scene keeps the scene ones",
          "[render][display]") {
  Scratch scratch;
  const DisplayImage input = white_square();
  const std::string in = write(scratch, "square.png", input);
  Result r = bloom_render("--input " + in + " --chain bloom --out " + scratch / "display.png");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const DisplayImage display = read(scratch / "display.png");
  // The square glows onto the grey around it.
  CHECK(display.pixels != input.pixels);
  CHECK(display.pixels[(18 * 48 + 24) * 3] > input.pixels[(18 * 48 + 24) * 3]);

  // Scene-referred, bloom's threshold is 1: an SDR frame has nothing above it, nothing blooms.
  r = bloom_render("--input " + in + " --chain bloom --defaults scene --out " + scratch / "scene.png");
  REQUIRE(r.exit_code == 0);
  CHECK(read(scratch / "scene.png").pixels == input.pixels);
  // The display defaults are bloom's documented 0.6 and 0.2.
  r = bloom_render("--input " + in + " --chain bloom --defaults scene --set bloom.threshold=0.6 --set bloom.knee=0.2 "
                   "--out " + scratch / "set.png");
  REQUIRE(r.exit_code == 0);
  CHECK(read(scratch / "set.png").pixels == display.pixels);
}

TEST_CASE("an EXR made from an 8-bit frame gives, with --defaults display, what the frame gives", "[render][display]") {
  Scratch scratch;
  const std::string in = write(scratch, "square.png", white_square());
  REQUIRE(bloom_render("--input " + in + " --chain '' --out " + scratch / "decoded.exr").exit_code == 0);
  REQUIRE(bloom_render("--input " + in + " --chain bloom --out " + scratch / "from_png.exr").exit_code == 0);
  REQUIRE(bloom_render("--input " + scratch / "decoded.exr" + " --chain bloom --defaults display --out " +
                       scratch / "from_exr.exr").exit_code == 0);
  REQUIRE(bloom_render("--input " + scratch / "decoded.exr" + " --chain bloom --out " + scratch / "scene.exr")
              .exit_code == 0);
  pfx::app::Image from_png, from_exr, scene;
  std::string error;
  REQUIRE(pfx::app::read_exr(scratch / "from_png.exr", &from_png, &error));
  REQUIRE(pfx::app::read_exr(scratch / "from_exr.exr", &from_exr, &error));
  REQUIRE(pfx::app::read_exr(scratch / "scene.exr", &scene, &error));
  CHECK(from_exr.rgba == from_png.rgba);
  CHECK(scene.rgba != from_png.rgba);  // an EXR alone is scene-referred
}

TEST_CASE("options that do not fit an 8-bit input, or its absence, are usage errors, and a damaged PNG exits 3",
          "[render][display][errors]") {
  Scratch scratch;
  const std::string in = write(scratch, "codes.png", every_code(3));
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"--input " + in + " --transfer gamma --json", "--transfer: transfer 'gamma': expected srgb or linear"},
      {"--input " + in + " --defaults hdr --json", "--defaults hdr: expected scene or display"},
      {"--demo-image --transfer linear --json", "--transfer goes with an 8-bit --input"},
      {"--input " + in + " --exposure 1 --json", "--exposure and --tone tone-map an HDR input"},
      {"--input " + in + " --tone aces --json", "--exposure and --tone tone-map an HDR input"},
      {"--input " + in + " --depth z.exr --json", "--depth and --layer go with an EXR --input"},
  };
  for (const auto& c : cases) {
    Result r = pfx_render(c.args);
    INFO(c.args << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
  }
  std::ofstream(scratch / "broken.png") << "\x89PNG\r\n\x1a\n not really";
  Result r = pfx_render("--input " + scratch / "broken.png" + " --json");
  CHECK(r.exit_code == 3);
  CHECK(r.err.find(scratch / "broken.png") != std::string::npos);
}

namespace {

// A ReShade effect that inverts the sRGB codes it is handed: 255 - code, exact in float.
const char* const kInvertFx = R"(#include "ReShade.fxh"
sampler Point { Texture = ReShade::BackBufferTex; MagFilter = POINT; MinFilter = POINT; };
float4 Invert(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return float4(1.0 - tex2D(Point, uv).rgb, 1.0); }
technique Invert { pass { VertexShader = PostProcessVS; PixelShader = Invert; } }
)";

// The passes of a --json report that are the chain's own conversions.
std::vector<std::string> chain_passes(const std::string& report) {
  std::vector<std::string> names;
  const nlohmann::json parsed = nlohmann::json::parse(report);
  for (const auto& pass : parsed["passes"])
    if (pass["effect"] == "chain") names.push_back(pass["pass"]);
  return names;
}

}  // namespace

TEST_CASE("a chain of FX effects over an 8-bit input converts nothing, and over an EXR once at each end",
          "[render][display][fx]") {
  Scratch scratch;
  std::ofstream(scratch / "Invert.fx") << kInvertFx;
  ::setenv("PFX_FX_PATH", scratch.dir.c_str(), 1);  // the FX plugin's folders, for the child
  const DisplayImage input = every_code(4);
  const std::string in = write(scratch, "codes.png", input);
  Result r = bloom_render("--input " + in + " --chain fx_invert,fx_invert --out " + scratch / "twice.png" + " --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(chain_passes(r.out).empty());
  CHECK(nlohmann::json::parse(r.out)["passes"].size() == 4);  // each: begin, and its one pass
  CHECK(read(scratch / "twice.png").pixels == input.pixels);  // inverted twice, code for code

  pfx::app::Image linear;
  linear.width = 16;
  linear.height = 4;
  for (int i = 0; i < 64; ++i)
    for (const float v : {0.1f * (i % 11), 0.5f, 2.0f, 1.0f}) linear.rgba.push_back(v);
  std::string error;
  REQUIRE(pfx::app::write_exr(scratch / "linear.exr", linear, pfx::app::ExrPixelType::Half, &error));
  r = bloom_render("--input " + scratch / "linear.exr" + " --chain fx_invert,fx_invert --out " + scratch / "out.exr" + " --json");
  REQUIRE(r.exit_code == 0);
  CHECK(chain_passes(r.out) == std::vector<std::string>{"colour to sRGB codes", "sRGB codes to output"});
  ::unsetenv("PFX_FX_PATH");
}
