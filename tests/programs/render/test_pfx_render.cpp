// pfx-render as a user runs it: exit codes, --help, --list, --json, the files it writes.
#include <catch2/catch.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "exr_io.hpp"
#include "png_io.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::Result;
using pfx::test::Scratch;

TEST_CASE("help documents every option and exit code", "[render]") {
  Result r = pfx_render("--help", false);
  CHECK(r.exit_code == 0);
  for (const char* option : {"--plugins", "--demo", "--demo-image", "--lights", "--seed", "--input", "--layer", "--depth", "--size", "--camera", "--chain", "--set",
                             "--out", "--json", "--list", "--float", "--exposure", "--tone", "--timing", "--preset", "--transfer", "--defaults",
                             "exit codes: 0 ok, 1 internal", "2 usage", "3 bad input file", "4 plugin or effect error"})
    CHECK(r.out.find(option) != std::string::npos);
}

TEST_CASE("usage errors exit 2 with a message", "[render][errors]") {
  CHECK(pfx_render("").exit_code == 2);
  CHECK(pfx_render("--demo --input x.exr --json").exit_code == 2);
  CHECK(pfx_render("--demo --out x.tiff").exit_code == 2);
  CHECK(pfx_render("--demo --size 0x5 --json").exit_code == 2);
  CHECK(pfx_render("--demo --camera fovy=45,near=1,far=1 --json").exit_code == 2);
  Result r = pfx_render("--demo --json --set gain.gain=nan");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("gain.gain: NaN is not a valid value") != std::string::npos);
  r = pfx_render("--frobnicate");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("unknown option '--frobnicate'") != std::string::npos);
}

TEST_CASE("bad input files exit 3 naming the file", "[render][errors][hard]") {
  Scratch scratch;
  Result r = pfx_render("--input " + scratch / "missing.exr" + " --json");
  CHECK(r.exit_code == 3);
  CHECK(r.err.find(scratch / "missing.exr") != std::string::npos);
  std::ofstream(scratch / "text.exr") << "this is not an EXR file\n";
  r = pfx_render("--input " + scratch / "text.exr" + " --json");
  CHECK(r.exit_code == 3);
  CHECK(r.err.find(scratch / "text.exr") != std::string::npos);
}

TEST_CASE("an unknown effect exits 4", "[render][errors]") {
  Result r = pfx_render("--demo --size 8x8 --chain nothing --json");
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("unknown effect 'nothing'") != std::string::npos);
}

TEST_CASE("the chain none runs no effect, as every other host takes it", "[render]") {
  Scratch scratch;
  const std::string none = (scratch.dir / "none.png").string(), empty = (scratch.dir / "empty.png").string();
  Result r = pfx_render("--demo-image --size 8x8 --chain none --out " + none);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("unknown effect") == std::string::npos);
  CHECK(r.err.find("no effect ran") != std::string::npos);
  // The same picture as an empty chain gives.
  REQUIRE(pfx_render("--demo-image --size 8x8 --chain '' --out " + empty).exit_code == 0);
  std::ifstream a(none, std::ios::binary), b(empty, std::ios::binary);
  CHECK(std::string(std::istreambuf_iterator<char>(a), {}) == std::string(std::istreambuf_iterator<char>(b), {}));
}

TEST_CASE("list in JSON lists the fixture effects with their parameter metadata", "[render]") {
  Result r = pfx_render("--list --json");
  REQUIRE(r.exit_code == 0);
  auto json = nlohmann::json::parse(r.out);
  REQUIRE(json["plugins"].size() == 1);
  const auto& effects = json["plugins"][0]["effects"];
  REQUIRE(effects.size() == 2);
  CHECK(effects[0]["id"] == "gain");
  const auto& gain = effects[0]["parameters"][0];
  CHECK(gain["key"] == "gain.gain");
  CHECK(gain["type"] == "float");
  CHECK(gain["default"] == 1.0);
  CHECK(gain["hard_max"] == 1000.0);
  CHECK(effects[0]["parameters"][1]["items"][1]["id"] == "luma");
}

TEST_CASE("demo with JSON reports passes, memory and output statistics, and its files land complete", "[render]") {
  Scratch scratch;
  Result plain = pfx_render("--demo --size 64x48 --chain gain --json");
  REQUIRE(plain.exit_code == 0);
  auto before = nlohmann::json::parse(plain.out);
  CHECK(before["effects"].empty());  // gain 1 is a no-op
  CHECK(before["passes"].empty());

  Result r = pfx_render("--demo --size 64x48 --chain gain,boxblur --set gain.gain=2 --set boxblur.radius=1 --json --out " +
                        scratch / "a.exr" + " --out " + scratch / "a.png");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  auto json = nlohmann::json::parse(r.out);
  CHECK(json["renderer"].get<std::string>().find("4.5") != std::string::npos);
  CHECK(json["effects"] == nlohmann::json::array({"gain", "boxblur"}));
  CHECK(json["passes"].size() == 4);
  CHECK(json["passes"][0]["effect"] == "gain");
  // gain's 64x48 output is an intermediate; boxblur's two 32x24 targets: 8 bytes a pixel.
  CHECK(json["peak_target_bytes"] == 64 * 48 * 8 + 2 * 32 * 24 * 8);
  CHECK(json["output"]["width"] == 64);
  CHECK(json["output"]["nonfinite"] == 0);
  // A blur keeps the mean (up to the edges) and gain 2 doubles it.
  for (int c = 0; c < 3; ++c)
    CHECK(json["output"]["mean"][c].get<double>() ==
          Approx(2 * before["output"]["mean"][c].get<double>()).epsilon(0.05));
  CHECK(scratch.files() == std::vector<std::string>{"a.exr", "a.png"});

  pfx::app::Image exr;
  std::string error;
  REQUIRE(pfx::app::read_exr(scratch / "a.exr", &exr, &error));
  CHECK(exr.width == 64);
  CHECK(exr.height == 48);
  pfx::app::DisplayImage png;
  REQUIRE(pfx::app::read_png(scratch / "a.png", &png, &error));
  CHECK(png.width == 64);
}

TEST_CASE("an EXR written by pfx-render reads back as input, depth included", "[render]") {
  Scratch scratch;
  REQUIRE(pfx_render("--demo --size 40x30 --chain gain --out " + scratch / "in.exr --float").exit_code == 0);
  Result r = pfx_render("--input " + scratch / "in.exr" + " --chain gain --set gain.gain=0.5 --json --out " +
                        scratch / "out.exr");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  pfx::app::Image in, out;
  std::string error;
  REQUIRE(pfx::app::read_exr(scratch / "in.exr", &in, &error));
  REQUIRE(pfx::app::read_exr(scratch / "out.exr", &out, &error));
  for (size_t i = 0; i < in.rgba.size(); i += 4) REQUIRE(out.rgba[i] == Approx(in.rgba[i] * 0.5).epsilon(1.0 / 512));
}

TEST_CASE("an output into a missing folder fails without leaving anything behind", "[render][errors]") {
  Scratch scratch;
  Result r = pfx_render("--demo --size 8x8 --out " + scratch / "no/such/dir/x.exr");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("x.exr") != std::string::npos);
}

TEST_CASE("the demo scene reports its lights, --lights adds to them, and the options check their values", "[render]") {
  Result r = pfx_render("--demo --size 32x18 --chain gain --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["lights"] == 400);
  r = pfx_render("--demo --size 32x18 --lights 25 --seed 9 --chain gain --json");
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["lights"] == 425);
  r = pfx_render("--demo-image --size 32x18 --chain gain --json");
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["lights"] == 0);
  CHECK(pfx_render("--demo --lights -3 --json").exit_code == 2);
  CHECK(pfx_render("--demo --lights many --json").exit_code == 2);
  CHECK(pfx_render("--demo-image --lights 3 --json").exit_code == 2);
  CHECK(pfx_render("--demo --demo-image --json").exit_code == 2);
  r = pfx_render("--demo --size 8x8 --camera near=500 --json");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("far must be greater than near") != std::string::npos);
}
