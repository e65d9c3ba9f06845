// pfx-view in a window, under Xvfb (ctest runs this program through xvfb-run): the scripted
// screenshot against pfx-render for the same preset, presets saved by the viewer reproduced by
// pfx-render, an image input, the error exits, and hot reload of a fixture plugin while the
// viewer runs. Frames are small (320x180) so each run takes about a second on llvmpipe.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "exr_io.hpp"
#include "png_io.hpp"
#include "view_process.hpp"

namespace fs = std::filesystem;
using pfx::test::compare_png;
using pfx::test::run_program;

namespace {

// A PNG of every code in red and green, alpha moving too, blue dark (where a decode and encode
// again on the GPU would drift most), 256x6; written to `path` and returned.
pfx::app::DisplayImage every_code(const std::string& path) {
  pfx::app::DisplayImage picture;
  picture.width = 256;
  picture.height = 6;
  picture.channels = 4;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x)
      for (int v : {x, 255 - x, x % 16, 255 - y * 40}) picture.pixels.push_back(uint8_t(v));
  std::string error;
  REQUIRE(pfx::app::write_png(path, picture, &error));
  return picture;
}

// The largest difference of `result` (RGBA) from Grade.fx's multiply applied to the codes of
// `picture` once per gain, rounding to a code after each, alpha kept: computed here, on the CPU.
int worst_against_gains(const pfx::app::DisplayImage& picture, const pfx::app::DisplayImage& result,
                        const std::vector<double>& gains) {
  REQUIRE(result.channels == 4);
  REQUIRE(result.pixels.size() == picture.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < picture.pixels.size(); ++i) {
    int expected = picture.pixels[i];
    if (i % 4 != 3)
      for (double gain : gains) expected = std::min(255, int(std::lround(expected * gain)));
    worst = std::max(worst, std::abs(int(result.pixels[i]) - expected));
  }
  return worst;
}

// The same 8-bit result, give or take one code value for a GL that rounds differently in a window
// than headless; on average well under a tenth of a code value. (On llvmpipe both are bit-identical.)
constexpr int kPngMaxDifference = 1;
constexpr double kPngMeanDifference = 0.1;
// Half-float storage: 2^-10 relative.
constexpr double kExrRelativeDifference = 1.0 / 1024;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-view-test-" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir / name) << text; }
};

std::vector<std::string> with_plugins(const std::string& program, std::vector<std::string> args) {
  std::vector<std::string> argv = {program, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--plugins", PFX_TEST_PLUGIN_DIR};
  argv.insert(argv.end(), args.begin(), args.end());
  return argv;
}

std::vector<std::string> viewer(std::vector<std::string> args) { return with_plugins(PFX_VIEW, std::move(args)); }
std::vector<std::string> renderer(std::vector<std::string> args) { return with_plugins(PFX_RENDER, std::move(args)); }

void require_ok(const pfx::test::RunResult& result) {
  INFO(result.output);
  REQUIRE(result.exit_code == 0);
}

// A look that differs from the defaults in every part: chain order and flags, values, the camera
// and the display.
const char* const kLook = R"({
  "pfx_preset": 1,
  "chain": [{"effect": "gain", "enabled": true}, {"effect": "bloom", "enabled": true},
            {"effect": "boxblur", "enabled": false}],
  "parameters": {"gain": {"gain": 1.6}, "bloom": {"threshold": 0.6, "strength": 2.5, "tint": [1, 0.8, 0.6]},
                 "boxblur": {"radius": 3}},
  "camera": {"position": [9, 6, 14], "target": [0, 0.5, 0], "up": [0, 1, 0], "fovy_degrees": 55,
             "near": 0.2, "far": 300},
  "display": {"exposure_ev": 0.5, "tone": "aces"}
})";

}  // namespace

TEST_CASE("pfx-view help lists every option and the exit codes", "[view][window]") {
  auto r = run_program({PFX_VIEW, "--help"});
  require_ok(r);
  for (const char* text : {"--plugins", "--demo", "--demo-image", "--scene", "--input", "--depth", "--size", "--window", "--camera",
                           "--chain", "--set", "--preset", "--save-preset", "--no-watch", "--hide-panels", "--exposure", "--tone",
                           "--frames", "--screenshot", "--window-shot", "--shots", "SIGUSR1", "exit codes: 0 ok"})
    CHECK(r.output.find(text) != std::string::npos);
}

TEST_CASE("pfx-view without a display exits 1 and says how to run it headless", "[view][window][errors]") {
  auto r = run_program({"/usr/bin/env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", PFX_VIEW, "--frames", "1"});
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("xvfb-run") != std::string::npos);
}

TEST_CASE("pfx-view usage, input and effect errors exit 2, 3 and 4 with a message, a preset's unknown values are a warning", "[view][window][errors]") {
  Scratch scratch;
  auto r = run_program(viewer({"--frames", "1", "--set", "gain.gain=nan"}));
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("gain.gain") != std::string::npos);
  r = run_program(viewer({"--frames", "1", "--preset", scratch / "none.json"}));
  CHECK(r.exit_code == 3);
  CHECK(r.output.find(scratch / "none.json" + ": cannot open the preset") != std::string::npos);
  // What a preset names that is not loaded is left out with a warning, as in every host.
  scratch.write("other.json", R"({"pfx_preset": 1, "parameters": {"nosuch": {"x": 1}}})");
  r = run_program(viewer({"--frames", "1", "--preset", scratch / "other.json"}));
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("other.json: left out: nosuch.x (not loaded)") != std::string::npos);
  r = run_program(viewer({"--frames", "1", "--input", scratch / "none.exr"}));
  CHECK(r.exit_code == 3);
  r = run_program(viewer({"--frames", "1", "--chain", "gain,nosuch"}));
  CHECK(r.exit_code == 4);
  CHECK(r.output.find("unknown effect 'nosuch'") != std::string::npos);
}

TEST_CASE("20 frames of the demo in the viewer match pfx-render for the same preset", "[view][window]") {
  Scratch scratch;
  scratch.write("look.json", kLook);
  require_ok(run_program(viewer({"--demo", "--size", "320x180", "--preset", scratch / "look.json", "--frames", "20",
                                 "--screenshot", scratch / "view.png"})));
  require_ok(run_program(renderer({"--demo", "--size", "320x180", "--preset", scratch / "look.json", "--out",
                                   scratch / "render.png", "--out", scratch / "render.exr"})));
  auto d = compare_png(scratch / "view.png", scratch / "render.png");
  CHECK(d.width == 320);
  CHECK(d.height == 180);
  CHECK(d.max <= kPngMaxDifference);
  CHECK(d.mean <= kPngMeanDifference);
  CHECK(pfx::test::exr_relative_difference(scratch / "view.exr", scratch / "render.exr") <= kExrRelativeDifference);

  // The preset matters to both: without it the picture is far from this one.
  require_ok(run_program(renderer({"--demo", "--size", "320x180", "--chain", "bloom", "--out", scratch / "plain.png"})));
  CHECK(compare_png(scratch / "plain.png", scratch / "render.png").mean > 5.0);
}

TEST_CASE("a preset saved by the viewer holds what it showed and pfx-render reproduces it", "[view][window][preset]") {
  Scratch scratch;
  scratch.write("look.json", kLook);
  // The command line changes the preset's look; the saved preset must carry the changes.
  require_ok(run_program(viewer({"--demo", "--size", "320x180", "--preset", scratch / "look.json", "--set",
                                 "gain.gain=0.7", "--camera", "fovy=40", "--tone", "reinhard", "--frames", "2",
                                 "--screenshot", scratch / "view.png", "--save-preset", scratch / "saved.json"})));
  std::ifstream in(scratch / "saved.json");
  const auto saved = nlohmann::json::parse(in);
  CHECK(saved["pfx_preset"] == 1);
  CHECK(saved["chain"] == nlohmann::json::parse(R"([{"effect": "gain", "enabled": true}, {"effect": "bloom", "enabled": true},
                                                    {"effect": "boxblur", "enabled": false}])"));
  CHECK(saved["parameters"]["gain"]["gain"] == 0.7);
  CHECK(saved["parameters"]["bloom"]["strength"] == 2.5);
  CHECK(saved["parameters"]["boxblur"]["radius"] == 3);
  CHECK(saved["camera"]["position"] == nlohmann::json::parse("[9, 6, 14]"));
  CHECK(saved["camera"]["fovy_degrees"].get<double>() == Approx(40).epsilon(1e-12));
  CHECK(saved["camera"]["far"] == 300);
  CHECK(saved["display"]["tone"] == "reinhard");
  CHECK(saved["display"]["exposure_ev"] == 0.5);

  require_ok(run_program(renderer({"--demo", "--size", "320x180", "--preset", scratch / "saved.json", "--out",
                                   scratch / "saved.png"})));
  auto d = compare_png(scratch / "view.png", scratch / "saved.png");
  CHECK(d.max <= kPngMaxDifference);
  CHECK(d.mean <= kPngMeanDifference);
  // And it is the same look as the original preset with the same changes, given to pfx-render.
  require_ok(run_program(renderer({"--demo", "--size", "320x180", "--preset", scratch / "look.json", "--set",
                                   "gain.gain=0.7", "--camera", "fovy=40", "--tone", "reinhard", "--out",
                                   scratch / "changed.png"})));
  CHECK(compare_png(scratch / "saved.png", scratch / "changed.png").max == 0);
}

TEST_CASE("an EXR image with depth through the viewer matches pfx-render", "[view][window]") {
  Scratch scratch;
  require_ok(run_program(renderer({"--demo-image", "--size", "96x64", "--chain", "", "--out", scratch / "in.exr"})));
  require_ok(run_program(viewer({"--input", scratch / "in.exr", "--chain", "gain,boxblur", "--set", "gain.gain=3",
                                 "--set", "boxblur.radius=2", "--frames", "3", "--screenshot", scratch / "view.png"})));
  require_ok(run_program(renderer({"--input", scratch / "in.exr", "--chain", "gain,boxblur", "--set", "gain.gain=3",
                                   "--set", "boxblur.radius=2", "--out", scratch / "render.png", "--out",
                                   scratch / "render.exr"})));
  auto d = compare_png(scratch / "view.png", scratch / "render.png");
  CHECK(d.width == 96);
  CHECK(d.max <= kPngMaxDifference);
  CHECK(pfx::test::exr_relative_difference(scratch / "view.exr", scratch / "render.exr") <= kExrRelativeDifference);
}

TEST_CASE("an OBJ scene through the viewer matches pfx-render --scene", "[view][window]") {
  Scratch scratch;
  // A box on a floor, the box glowing so the bloom has something to spread.
  scratch.write("glow.mtl", "newmtl floor\nKd 0.6 0.6 0.6\nnewmtl glow\nKd 0.2 0.2 0.2\nKe 8 4 1\n");
  scratch.write("box.obj",
                "mtllib glow.mtl\n"
                "v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\n"
                "v -1 0 -1\nv 1 0 -1\nv 1 2 -1\nv -1 2 -1\nv -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\n"
                "usemtl floor\nf 1 4 3 2\n"
                "usemtl glow\nf 5 8 7 6\nf 9 10 11 12\nf 5 9 12 8\nf 6 7 11 10\nf 8 12 11 7\n");
  require_ok(run_program(viewer({"--scene", scratch / "box.obj", "--lights", "20", "--size", "160x120", "--chain",
                                 "bloom", "--frames", "2", "--screenshot", scratch / "view.png"})));
  require_ok(run_program(renderer({"--scene", scratch / "box.obj", "--lights", "20", "--size", "160x120", "--chain",
                                   "bloom", "--out", scratch / "render.png", "--out", scratch / "render.exr"})));
  auto d = compare_png(scratch / "view.png", scratch / "render.png");
  CHECK(d.max <= kPngMaxDifference);
  CHECK(d.mean <= kPngMeanDifference);
  CHECK(pfx::test::exr_relative_difference(scratch / "view.exr", scratch / "render.exr") <= kExrRelativeDifference);
  // Not an empty picture: the glowing box (emission 8, 4, 1) saturates red somewhere.
  pfx::app::DisplayImage shown;
  std::string error;
  REQUIRE(pfx::app::read_png(scratch / "view.png", &shown, &error));
  int brightest_red = 0;
  for (size_t i = 0; i < shown.pixels.size(); i += size_t(shown.channels)) brightest_red = std::max(brightest_red, int(shown.pixels[i]));
  CHECK(brightest_red == 255);
  auto r = run_program(viewer({"--scene", scratch / "none.obj", "--frames", "1"}));
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("none.obj") != std::string::npos);
}

TEST_CASE("the window shows what the screenshot holds: the display shader tone-maps as pfx-render does", "[view][window]") {
  Scratch scratch;
  // Every kind of value the display must handle: ordinary, tiny, above 1, above the half maximum,
  // infinite, negative and NaN, over a gradient.
  pfx::app::Image image;
  image.width = 64;
  image.height = 32;
  image.rgba.resize(image.pixel_count() * 4);
  const float specials[] = {0.5f, 1e-3f, 3.0f, 70000.0f, INFINITY, -1.0f, -INFINITY, NAN};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      p[0] = float(x) / 16.0f;
      p[1] = float(y) / 8.0f;
      p[2] = specials[(x / 8) % 8];
      p[3] = 1.0f;
      if (y < 4) p[0] = p[1] = p[2] = specials[(x / 8) % 8];
    }
  std::string error;
  REQUIRE(pfx::app::write_exr(scratch / "hard.exr", image, pfx::app::ExrPixelType::Float, &error));
  for (const char* tone : {"linear", "reinhard", "aces"}) {
    INFO(tone);
    require_ok(run_program(viewer({"--input", scratch / "hard.exr", "--window", "64x32", "--chain", "", "--hide-panels",
                                   "--tone", tone, "--exposure", "0.7", "--frames", "2", "--screenshot",
                                   scratch / "frame.png", "--window-shot", scratch / "window.png"})));
    auto d = compare_png(scratch / "window.png", scratch / "frame.png");
    CHECK(d.max <= kPngMaxDifference);
    CHECK(d.mean <= kPngMeanDifference);
  }
}

TEST_CASE("an 8-bit picture stays 8-bit through an all-FX chain in the viewer: no conversion pass, the grade's codes, "
          "pfx-render's bytes, and the window shows them",
          "[view][window][fx]") {
  Scratch scratch;
  const pfx::app::DisplayImage picture = every_code(scratch / "codes.png");
  std::string error;
  const std::string fx_path = std::string("PFX_FX_PATH=") + PFX_FX_TEST_SHADERS;
  const std::vector<std::string> look = {"--chain", "fx_grade,fx_grade", "--set", "fx_grade#1.gain=1.3", "--set",
                                         "fx_grade#2.gain=0.9"};
  std::vector<std::string> view = {"/usr/bin/env", fx_path, PFX_VIEW, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input",
                                   scratch / "codes.png", "--window", "256x6", "--hide-panels", "--frames", "2",
                                   "--screenshot", scratch / "view.png", "--window-shot", scratch / "window.png", "-v"};
  view.insert(view.end(), look.begin(), look.end());
  const pfx::test::RunResult shown = run_program(view);
  require_ok(shown);

  // The plan: each effect's own passes and nothing of the chain's (no conversion to linear light).
  const size_t at = shown.output.find("pfx-view: passes: ");
  REQUIRE(at != std::string::npos);
  const std::string passes = shown.output.substr(at, shown.output.find('\n', at) - at);
  INFO(passes);
  CHECK(passes.find("fx_grade/") != std::string::npos);
  CHECK(passes.find("chain/") == std::string::npos);

  // The grade in sRGB codes, as ReShade runs it: each instance multiplies and rounds to a code.
  pfx::app::DisplayImage result;
  REQUIRE(pfx::app::read_png(scratch / "view.png", &result, &error));
  CHECK(worst_against_gains(picture, result, {1.3, 0.9}) <= 1);  // a product on a half code rounds either way

  // pfx-render gives the same bytes from the same PNG, and the window shows them as they are.
  std::vector<std::string> render = {"/usr/bin/env", fx_path, PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR,
                                     "--input", scratch / "codes.png", "--out", scratch / "render.png"};
  render.insert(render.end(), look.begin(), look.end());
  require_ok(run_program(render));
  CHECK(compare_png(scratch / "view.png", scratch / "render.png").max == 0);
  pfx::app::DisplayImage window;
  REQUIRE(pfx::app::read_png(scratch / "window.png", &window, &error));
  REQUIRE(window.channels == 3);
  REQUIRE(window.pixels.size() == result.pixels.size() / 4 * 3);
  int window_worst = 0;
  for (size_t p = 0; p < window.pixels.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      window_worst = std::max(window_worst, std::abs(int(window.pixels[p * 3 + c]) - int(result.pixels[p * 4 + c])));
  CHECK(window_worst == 0);
}

TEST_CASE("a value edited mid-run in the viewer gives the new picture at once from live uniforms, then the same "
          "pixels from programs that hold it as a constant",
          "[view][window][fx]") {
  Scratch scratch;
  const pfx::app::DisplayImage picture = every_code(scratch / "codes.png");
  const std::string fx_path = std::string("PFX_FX_PATH=") + PFX_FX_TEST_SHADERS;
  // The frame of the edit itself runs live programs (the value has only just moved); 44 frames
  // later, at least 0.73 s on, the programs hold it as a constant (it settles after 0.5 s).
  auto view = [&](const std::string& frames, const std::string& shot) {
    const pfx::test::RunResult r = run_program(
        {"/usr/bin/env", fx_path, PFX_VIEW, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", scratch / "codes.png",
         "--chain", "fx_grade", "--window", "256x6", "--hide-panels", "--frames", frames, "--edit",
         "2:fx_grade.gain=1.3", "--screenshot", scratch / shot, "-v"});
    require_ok(r);
    return r.output;
  };
  // The value of "uniforms_as_constants" in each report of fx_grade the viewer printed, in order.
  auto constants = [](const std::string& log) {
    std::vector<int> counts;
    const std::string key = "\"uniforms_as_constants\": ";
    for (size_t at = log.find(key); at != std::string::npos; at = log.find(key, at + 1))
      counts.push_back(std::atoi(log.c_str() + at + key.size()));
    return counts;
  };
  const std::string live_log = view("2", "live.png"), settled_log = view("45", "settled.png");
  INFO(live_log);
  INFO(settled_log);
  // Grade's four parameters are constants from the first frame, none at the edit, all again later.
  CHECK(constants(live_log) == std::vector<int>{4, 0});
  CHECK(constants(settled_log) == std::vector<int>{4, 0, 4});

  std::string error;
  pfx::app::DisplayImage live, settled;
  REQUIRE(pfx::app::read_png(scratch / "live.png", &live, &error));
  REQUIRE(pfx::app::read_png(scratch / "settled.png", &settled, &error));
  CHECK(worst_against_gains(picture, live, {1.3}) <= 1);
  CHECK(compare_png(scratch / "live.png", scratch / "settled.png").max == 0);
  // pfx-render, given the value from the start, runs the same constants: the same bytes.
  require_ok(run_program({"/usr/bin/env", fx_path, PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input",
                          scratch / "codes.png", "--chain", "fx_grade", "--set", "fx_grade.gain=1.3", "--out",
                          scratch / "render.png"}));
  CHECK(compare_png(scratch / "settled.png", scratch / "render.png").max == 0);
}
