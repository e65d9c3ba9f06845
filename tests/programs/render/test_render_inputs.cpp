// Input files as users have them, through read_input_image and pfx-render end to end: a depth
// file with only Z or only R, a colour file with a lone channel, layers and --layer, and what
// --json and the log say was read.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "exr_channel_writer.hpp"
#include "input_image.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::Result;
using pfx::test::Scratch;

namespace {

constexpr int kW = 8, kH = 6;

std::vector<float> filled(float value) { return std::vector<float>(kW * kH, value); }

std::vector<float> ramp(float base) {
  std::vector<float> v;
  for (int i = 0; i < kW * kH; ++i) v.push_back(base + 0.125f * static_cast<float>(i));
  return v;
}

void write_rgb(const std::string& path) {
  pfx_test::write_exr_channels(path, kW, kH,
                               {{"R", filled(0.5f)}, {"G", filled(0.25f)}, {"B", filled(1.0f)}, {"Z", filled(99.0f)}});
}

}  // namespace

TEST_CASE("read_input_image: a --depth file's Z, or its R, replaces the input's depth", "[render][inputs]") {
  Scratch scratch;
  write_rgb(scratch / "rgb.exr");
  pfx_test::write_exr_channels(scratch / "z.exr", kW, kH, {{"Z", ramp(3.0f)}});
  pfx_test::write_exr_channels(scratch / "r.exr", kW, kH, {{"R", ramp(7.0f), Imf::HALF}});
  for (const auto& [file, channel, values] :
       {std::tuple{"z.exr", "Z", ramp(3.0f)}, std::tuple{"r.exr", "R", ramp(7.0f)}}) {
    pfx::app::InputFiles files;
    files.input = scratch / "rgb.exr";
    files.depth = scratch / file;
    pfx::app::Image image;
    pfx::app::InputReport report;
    std::string error;
    REQUIRE(pfx::app::read_input_image(files, &image, &report, &error));
    CHECK(image.depth == values);
    CHECK(image.rgba[0] == 0.5f);
    CHECK(report.color == "R, G, B (no A: alpha 1); depth Z");
    CHECK(report.depth == std::string("depth ") + channel);
  }
}

TEST_CASE("read_input_image: a --depth file of another size is refused with both sizes", "[render][inputs]") {
  Scratch scratch;
  write_rgb(scratch / "rgb.exr");
  pfx_test::write_exr_channels(scratch / "small.exr", 2, 2, {{"Z", std::vector<float>(4, 1.0f)}});
  pfx::app::InputFiles files;
  files.input = scratch / "rgb.exr";
  files.depth = scratch / "small.exr";
  pfx::app::Image image;
  std::string error;
  CHECK_FALSE(pfx::app::read_input_image(files, &image, nullptr, &error));
  CHECK(error == files.depth + ": depth is 2x2 but the image is 8x6");
  CHECK(image.width == 0);  // untouched
}

TEST_CASE("pfx-render --depth reads a Z-only and an R-only file and says which channel it took", "[render][inputs]") {
  Scratch scratch;
  write_rgb(scratch / "rgb.exr");
  pfx_test::write_exr_channels(scratch / "z.exr", kW, kH, {{"Z", ramp(3.0f)}});
  pfx_test::write_exr_channels(scratch / "r.exr", kW, kH, {{"R", ramp(3.0f)}});
  for (const auto& [file, channel] : {std::pair{"z.exr", "Z"}, std::pair{"r.exr", "R"}}) {
    Result r = pfx_render("--input " + scratch / "rgb.exr" + " --depth " + scratch / file + " --chain gain --json");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["input"]["file"] == scratch / "rgb.exr");
    CHECK(json["input"]["read"] == "R, G, B (no A: alpha 1); depth Z");
    CHECK(json["input"]["depth"]["file"] == scratch / file);
    CHECK(json["input"]["depth"]["read"] == std::string("depth ") + channel);
    // Without --json, the log says the same.
    r = pfx_render("--input " + scratch / "rgb.exr" + " --depth " + scratch / file + " --chain gain --out " +
                   scratch / "out.exr");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("depth: " + scratch / file + ": depth " + channel + "\n") != std::string::npos);
  }
}

TEST_CASE("pfx-render --input of a G-only file renders G in its place, R and B 0", "[render][inputs]") {
  Scratch scratch;
  pfx_test::write_exr_channels(scratch / "g.exr", kW, kH, {{"G", filled(0.75f), Imf::HALF}});
  Result r = pfx_render("--input " + scratch / "g.exr" + " --chain gain --set gain.gain=2 --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto json = nlohmann::json::parse(r.out);
  CHECK(json["input"]["read"] == "G (no R, B: 0) (no A: alpha 1)");
  CHECK(json["output"]["mean"][0] == 0.0);
  CHECK(json["output"]["mean"][1].get<double>() == Approx(1.5));
  CHECK(json["output"]["mean"][2] == 0.0);
}

TEST_CASE("pfx-render --layer chooses among layers, and without it several are refused with their names",
          "[render][inputs]") {
  Scratch scratch;
  pfx_test::write_exr_channels(scratch / "layers.exr", kW, kH,
                               {{"diffuse.R", filled(0.5f)}, {"diffuse.G", filled(0.5f)}, {"diffuse.B", filled(0.5f)},
                                {"emission.R", filled(4.0f)}, {"emission.G", filled(2.0f)},
                                {"emission.B", filled(1.0f)}});
  Result r = pfx_render("--input " + scratch / "layers.exr" + " --chain gain --json");
  CHECK(r.exit_code == 3);
  CHECK(r.err.find(scratch / "layers.exr") != std::string::npos);
  CHECK(r.err.find("diffuse, emission") != std::string::npos);
  CHECK(r.err.find("--layer") != std::string::npos);

  r = pfx_render("--input " + scratch / "layers.exr" + " --layer emission --chain gain --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto json = nlohmann::json::parse(r.out);
  CHECK(json["input"]["read"] == "layer 'emission': R, G, B (no A: alpha 1)");
  CHECK(json["output"]["mean"][0].get<double>() == Approx(4.0));

  CHECK(pfx_render("--demo --layer emission --json").exit_code == 2);
}
