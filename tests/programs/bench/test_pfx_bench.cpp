// pfx-bench --quick as CI runs it: the copy unit, a row per effect, the files it promises.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_report.hpp"
#include "error_metrics.hpp"
#include "exr_io.hpp"
#include "png_io.hpp"
#include "suite.hpp"

namespace fs = std::filesystem;

TEST_CASE("quick bench measures the copy unit and every fixture effect", "[bench]") {
  const fs::path out = fs::temp_directory_path() / ("pfx-bench-test-" + std::to_string(::getpid()));
  std::string command = std::string(PFX_BENCH) + " --quick --plugins " PFX_TEST_PLUGIN_DIR " --out " + out.string() +
                        " > /dev/null 2>&1";
  int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::ifstream in(out / "bench.json");
  REQUIRE(in);
  auto json = nlohmann::json::parse(in);
  CHECK(json["renderer"].get<std::string>().find("4.5") != std::string::npos);
  REQUIRE(json["units"].size() == 1);
  CHECK(json["units"][0]["width"] == 640);
  CHECK(json["units"][0]["copy_ms"].get<double>() > 0);
  std::map<std::string, nlohmann::json> rows;
  for (const auto& row : json["rows"]) rows[row["effect"].get<std::string>()] = row;
  REQUIRE(rows.count("gain"));
  REQUIRE(rows.count("boxblur"));
  CHECK(rows["gain"]["pass_count"] == 0);  // a no-op at its defaults
  CHECK(rows["boxblur"]["pass_count"] == 3);
  CHECK(rows["boxblur"]["peak_target_bytes"] == 2 * 320 * 180 * 8);
  CHECK(rows["boxblur"]["ratio_to_copy"].get<double>() > 0);
  // The shift probe ran for the effect that does something, and not for the no-op.
  REQUIRE(rows["boxblur"].contains("shift"));
  CHECK(rows["boxblur"]["shift"]["shape_rms"].get<double>() >= 0);
  CHECK(rows["boxblur"]["shift"]["energy_cv"].get<double>() < 0.5);
  CHECK_FALSE(rows["gain"].contains("shift"));
  CHECK(fs::exists(out / "bench.md"));
  fs::remove_all(out);
}

TEST_CASE("bench --set takes gain#1 for gain and skips a row for an instance it does not run", "[bench][instances]") {
  const fs::path out = fs::temp_directory_path() / ("pfx-bench-instances-" + std::to_string(::getpid()));
  auto bench = [&](const std::string& set) {
    std::string command = std::string(PFX_BENCH) + " --quick --plugins " PFX_TEST_PLUGIN_DIR " --effects gain --set " +
                          set + " --out " + out.string() + " > /dev/null 2>&1";
    int status = std::system(command.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    std::ifstream in(out / "bench.json");
    REQUIRE(in);
    return nlohmann::json::parse(in);
  };
  // gain 2 is no longer a no-op: the row's one instance got the value.
  auto json = bench("gain#1.gain=2");
  REQUIRE(json["rows"].size() == 1);
  CHECK(json["rows"][0]["pass_count"] == 1);
  // A row runs one instance of its effect: a second one does not exist, and the note says so.
  json = bench("gain#2.gain=2");
  CHECK(json["rows"].empty());
  bool said = false;
  for (const auto& note : json["notes"])
    said |= note.get<std::string>().find("there is no gain#2, effect 'gain' has 1 instance") != std::string::npos;
  CHECK(said);
  fs::remove_all(out);
}

TEST_CASE("suite rows parse and malformed rows name their line", "[bench]") {
  std::vector<pfx::bench::SuiteRow> rows;
  std::string error;
  REQUIRE(pfx::bench::parse_suite("# comment\nbloom mode=chain levels=6\n\ndof\n", &rows, &error));
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].label() == "mode=chain levels=6");
  CHECK(rows[1].label() == "defaults");
  CHECK_FALSE(pfx::bench::parse_suite("bloom mode\n", &rows, &error));
  CHECK(error == "suite line 1: 'mode' is not param=value");
  REQUIRE(pfx::bench::parse_suite(pfx::bench::default_suite_text(), &rows, &error));
}

TEST_CASE("relative RMSE and max error against a reference", "[bench]") {
  // Reference (1,2,2) and (0,0,0); output off by (0,0,1) in the first pixel: RMSE 1/sqrt(9).
  std::vector<float> reference = {1, 2, 2, 1, 0, 0, 0, 1};
  std::vector<float> output = {1, 2, 3, 0, 0, 0, 0, 7};  // alpha is ignored
  auto metrics = pfx::bench::compare_rgb(output, reference);
  CHECK(metrics.relative_rmse == Approx(1.0 / 3.0));
  CHECK(metrics.max_abs == 1.0);
  // Relative to the change: the reference adds (0,0,1) and (0,0,0) to the input, so the error of 1
  // is as large as the change.
  const std::vector<float> input = {1, 2, 1, 1, 0, 0, 0, 1};
  CHECK(pfx::bench::compare_rgb(output, reference, &input).change_relative_rmse == Approx(1.0));
  CHECK(metrics.change_relative_rmse == -1.0);  // no input given
  output[0] = std::nanf("");
  CHECK(pfx::bench::compare_rgb(output, reference).nonfinite == 1);
}

TEST_CASE("bench on input frames with a ground truth and a halo mask", "[bench]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-bench-input-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  pfx::app::Image frame, mask;
  frame.width = mask.width = 24;
  frame.height = mask.height = 16;
  frame.rgba.assign(frame.pixel_count() * 4, 0.5f);
  frame.depth.assign(frame.pixel_count(), 3.0f);
  mask.rgba.assign(mask.pixel_count() * 4, 0.0f);
  for (int y = 4; y < 12; ++y)
    for (int x = 8; x < 16; ++x) mask.rgba[(y * 24 + x) * 4] = 1.0f;
  std::string error;
  REQUIRE(pfx::app::write_exr((dir / "frame.exr").string(), frame, pfx::app::ExrPixelType::Float, &error));
  REQUIRE(pfx::app::write_exr((dir / "mask.exr").string(), mask, pfx::app::ExrPixelType::Float, &error));
  const std::string base = std::string(PFX_BENCH) + " --frames 2 --warmup 0 --plugins " PFX_TEST_PLUGIN_DIR " --out " +
                           (dir / "out").string() + " --input " + (dir / "frame.exr").string();
  // The frame is its own truth: an effect that changes nothing has no error and no halo.
  int status = std::system((base + " --truth " + (dir / "frame.exr").string() + " --halo-mask " +
                            (dir / "mask.exr").string() + " --set gain.gain=1 > /dev/null 2>&1").c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::ifstream in(dir / "out" / "bench.json");
  auto json = nlohmann::json::parse(in);
  REQUIRE(json["units"].size() == 1);
  CHECK(json["units"][0]["width"] == 24);
  CHECK(json["units"][0]["source"] == (dir / "frame.exr").string());
  bool saw_gain = false;
  for (const auto& row : json["rows"]) {
    REQUIRE(row.contains("error_truth"));
    REQUIRE(row.contains("halo_px"));
    if (row["effect"] == "gain") {
      saw_gain = true;
      CHECK(row["error_truth"]["relative_rmse"] == 0.0);
      CHECK(row["halo_px"] == 0);
    }
  }
  CHECK(saw_gain);
  // A missing input is a bad input file (3); a truth per input is required (2).
  status = std::system((std::string(PFX_BENCH) + " --input " + (dir / "nope.exr").string() + " > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(status) == 3);
  status = std::system((base + " --truth a.exr --truth b.exr > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(status) == 2);
  fs::remove_all(dir);
}

// An 8-bit PNG is measured as every host of 8-bit frames runs the chain: its codes in 8-bit
// textures, handed as they are to an effect that promises to only sample its colour and draw its
// output (first_effect's tint: one pass, no target of pfx's own), converted to RGBA16F and back
// around one that does not (minimal's gain), as docs/architecture.md says the chain does. The
// same effects on an EXR frame run their own passes alone.
TEST_CASE("bench on an 8-bit PNG runs the chain on the 8-bit frame as hosts hand it over", "[bench]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-bench-png-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  pfx::app::DisplayImage png;
  png.width = 24;
  png.height = 16;
  png.channels = 3;
  for (int i = 0; i < png.width * png.height * 3; ++i) png.pixels.push_back(static_cast<uint8_t>(i * 7 % 256));
  std::string error;
  REQUIRE(pfx::app::write_png((dir / "frame.png").string(), png, &error));
  auto passes_of = [&](const std::string& plugins, const std::string& effect, const std::string& set) {
    const std::string command = std::string(PFX_BENCH) + " --frames 1 --warmup 0 --no-shift --plugins " + plugins +
                                " --effects " + effect + " --set " + set + " --input " + (dir / "frame.png").string() +
                                " --out " + (dir / "out").string() + " > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    std::ifstream in(dir / "out" / "bench.json");
    const auto json = nlohmann::json::parse(in);
    CHECK(json["units"][0]["source"] == (dir / "frame.png").string() + " (8-bit, as hosts hand it over)");
    CHECK(json["units"][0]["width"] == 24);
    std::vector<std::string> names;
    REQUIRE(json["rows"].size() == 1);
    for (const auto& pass : json["rows"][0]["passes"]) names.push_back(pass["pass"].get<std::string>());
    return names;
  };
  CHECK(passes_of(PFX_TEST_PLUGIN_DIR "/first_effect", "tint", "tint.tint=1,0.5,0.5") ==
        std::vector<std::string>{"tint"});
  CHECK(passes_of(PFX_TEST_PLUGIN_DIR, "gain", "gain.gain=2") ==
        std::vector<std::string>{"8-bit colour to RGBA16F", "gain", "RGBA16F to 8-bit output"});
  fs::remove_all(dir);
}
