// pfx-render over frame sequences: the name patterns and ranges, a failed frame failing alone,
// reruns that skip complete frames, --overwrite, and stopping on SIGTERM after a whole frame.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "exr_channel_writer.hpp"
#include "exr_io.hpp"
#include "frame_pattern.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::Result;
using pfx::test::Scratch;
namespace fs = std::filesystem;

namespace {

constexpr int kW = 8, kH = 6;

// Frame f's red channel: 0.01 * f + 0.001 * pixel index, so every frame differs.
float red(long long frame, int i) { return 0.01f * static_cast<float>(frame) + 0.001f * static_cast<float>(i); }

void write_frame(const std::string& path, long long frame) {
  std::vector<float> r, g(kW * kH, 0.25f), b(kW * kH, 0.5f);
  for (int i = 0; i < kW * kH; ++i) r.push_back(red(frame, i));
  pfx_test::write_exr_channels(path, kW, kH, {{"R", r}, {"G", g}, {"B", b}});
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// One JSON object per line: the frames, then the summary.
std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

std::string statuses(const std::vector<nlohmann::json>& lines) {
  std::string text;
  for (const auto& line : lines)
    if (line.contains("frame")) text += std::to_string(line["frame"].get<long long>()) + ":" +
                                        line["status"].get<std::string>() + " ";
  return text;
}

const std::string kGain = " --chain gain --set gain.gain=2";

}  // namespace

TEST_CASE("frame ranges A or A-B or A-BxS with reversed and negative ranges and zero steps refused", "[render][sequence]") {
  pfx::app::FrameRange range;
  std::string error;
  REQUIRE(pfx::app::parse_frame_range("1001-1240x2", &range, &error));
  CHECK(range.first == 1001);
  CHECK(range.count() == 120);
  CHECK(range.at(119) == 1239);  // 1240 itself is not on the step
  REQUIRE(pfx::app::parse_frame_range("7", &range, &error));
  CHECK((range.first == 7 && range.last == 7 && range.count() == 1));
  for (const char* bad : {"10-5", "-3", "-3-5", "1-5x0", "1-5x", "a-b", "1--5", "1000000000", ""}) {
    INFO(bad);
    CHECK_FALSE(pfx::app::parse_frame_range(bad, &range, &error));
    CHECK(error.rfind(std::string("--frames ") + bad + ": ", 0) == 0);
  }
}

TEST_CASE("frame name patterns %04d %d #### @@@@ and a lone @ with %% and numbers wider than the padding",
          "[render][sequence]") {
  pfx::app::FramePattern pattern;
  std::string error;
  for (const auto& [text, frame, path] :
       {std::tuple{"shot.%04d.exr", 7, "shot.0007.exr"}, std::tuple{"shot.%d.exr", 7, "shot.7.exr"},
        std::tuple{"a/shot.####.exr", 1001, "a/shot.1001.exr"}, std::tuple{"s.@@@@@@.png", 42, "s.000042.png"},
        std::tuple{"s.@.exr", 1234, "s.1234.exr"}, std::tuple{"s_##.exr", 12345, "s_12345.exr"},
        std::tuple{"100%%.#.exr", 3, "100%.3.exr"}}) {
    INFO(text);
    REQUIRE(pfx::app::parse_frame_pattern("--out", text, &pattern, &error));
    CHECK(pattern.path(frame) == path);
  }
  CHECK_FALSE(pfx::app::parse_frame_pattern("--out", "render@2x.####.png", &pattern, &error));
  CHECK(error == "--out render@2x.####.png: more than one frame number (%d, %0Nd, # or @); a file name may hold only one");
  CHECK_FALSE(pfx::app::parse_frame_pattern("--input", "shot.exr", &pattern, &error));
  CHECK(error.find("no frame number in the name") != std::string::npos);
  CHECK_FALSE(pfx::app::parse_frame_pattern("--out", "shot.%5d.exr", &pattern, &error));
  CHECK(error.find("a % must start %d, %0Nd") != std::string::npos);
}

TEST_CASE("pfx-render --frames: usage errors exit 2 and say what is wrong", "[render][sequence][errors]") {
  const Result help = pfx_render("--help", false);
  for (const char* text : {"--frames A-B[xS]", "--overwrite", "--report PATTERN", "--chunk N", "--chunk-index I", "--print-frames",
                           "5 some frames of a sequence failed"})
    CHECK(help.out.find(text) != std::string::npos);
  for (const auto& [args, message] :
       {std::pair{"--input in.%04d.exr --out out.exr", "--input in.%04d.exr names a frame sequence: give --frames"},
        std::pair{"--input in.%04d.exr --frames 1-3 --out out.exr", "--out out.exr: no frame number in the name"},
        std::pair{"--input in.exr --frames 1-3 --out o.#.exr", "--input in.exr: no frame number in the name"},
        std::pair{"--demo --frames 1-3 --out o.#.exr", "--frames goes with --input"},
        std::pair{"--input in.#.exr --frames 5-1 --out o.#.exr", "--frames 5-1: the last frame comes before"},
        std::pair{"--input in.exr --out o.exr --overwrite", "--overwrite goes with --frames"},
        std::pair{"--input in.#.exr --frames 1-3 --out o.#.exr --report r.json", "--report r.json: no frame number"},
        std::pair{"--input in.#.exr --frames 1-3 --out o.#.exr --chunk 0", "--chunk 0: expected a whole number from 1"},
        std::pair{"--input in.#.exr --frames 1-7 --out o.#.exr --chunk 3 --chunk-index 3",
                  "--chunk-index 3: the 7 frames in chunks of 3 make chunks 0 to 2"},
        std::pair{"--input in.#.exr --frames 1-3 --out o.#.exr --chunk-index 0", "--chunk-index goes with --chunk N"},
        std::pair{"--input in.exr --out o.exr --print-frames", "--print-frames goes with --frames"}}) {
    INFO(args);
    const Result r = pfx_render(args);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(message) != std::string::npos);
  }
}

TEST_CASE("pfx-render --frames renders each frame as a single render would and a missing or damaged "
          "input fails alone with exit code 5",
          "[render][sequence][hard]") {
  Scratch scratch;
  for (int frame : {1, 2, 3, 6}) write_frame(scratch / ("in." + std::to_string(1000 + frame) + ".exr"), frame);
  // 1004 missing; 1005 cut short, as a copy that died midway leaves it.
  write_frame(scratch / "whole.exr", 5);
  const std::string whole = read_bytes(scratch / "whole.exr");
  std::ofstream(scratch / "in.1005.exr", std::ios::binary) << whole.substr(0, whole.size() / 2);
  fs::remove(scratch / "whole.exr");

  const Result r = pfx_render("--input " + scratch / "in.%d.exr" + " --frames 1001-1006" + kGain + " --out " +
                              scratch / "out.####.exr" + " --out " + scratch / "out.@@@@.png" + " --report " +
                              scratch / "report.%d.json" + " --json");
  INFO(r.err);
  CHECK(r.exit_code == 5);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 7);
  CHECK(statuses(lines) == "1001:rendered 1002:rendered 1003:rendered 1004:failed 1005:failed 1006:rendered ");
  CHECK(lines[3]["error"] == scratch / "in.1004.exr" + ": no such file");
  CHECK(lines[4]["error"].get<std::string>().rfind(scratch / "in.1005.exr" + ": ", 0) == 0);
  CHECK(lines[6]["summary"]["failed"] == nlohmann::json({1004, 1005}));
  CHECK(lines[6]["summary"]["rendered"] == 4);
  CHECK(r.err.find("pfx-render: frame 1004: " + scratch / "in.1004.exr" + ": no such file") != std::string::npos);
  CHECK(r.err.find("6 frames: 4 rendered, 0 skipped (already complete), 2 failed (1004 1005)") != std::string::npos);
  // The per-frame reports say the same, failures included.
  std::ifstream report_file(scratch / "report.1004.json");
  CHECK(nlohmann::json::parse(report_file)["status"] == "failed");

  for (int frame : {1, 2, 3, 6}) {
    const std::string number = std::to_string(1000 + frame);
    INFO(number);
    pfx::app::Image image;
    std::string error;
    REQUIRE(pfx::app::read_exr(scratch / ("out." + number + ".exr"), &image, &error));
    // gain 2 over what write_frame wrote (half output: a relative error under 2^-11).
    for (int i = 0; i < kW * kH; ++i) CHECK(image.rgba[4 * i] == Approx(2 * red(frame, i)).epsilon(1e-3));
    CHECK(image.rgba[1] == Approx(0.5f));
    // Bit-identical to the frame rendered alone by another process.
    const Result single = pfx_render("--input " + scratch / ("in." + number + ".exr") + kGain + " --out " +
                                     scratch / "single.exr" + " --out " + scratch / "single.png");
    REQUIRE(single.exit_code == 0);
    CHECK(read_bytes(scratch / ("out." + number + ".exr")) == read_bytes(scratch / "single.exr"));
    CHECK(read_bytes(scratch / ("out." + number + ".png")) == read_bytes(scratch / "single.png"));
  }
  CHECK_FALSE(fs::exists(scratch / "out.1004.exr"));
  CHECK_FALSE(fs::exists(scratch / "out.1005.png"));
  for (const auto& name : scratch.files()) CHECK(name.find(".tmp-") == std::string::npos);
}

TEST_CASE("pfx-render --frames again skips frames whose outputs exist and renders missing outputs and "
          "--overwrite renders all",
          "[render][sequence]") {
  Scratch scratch;
  for (int frame = 1; frame <= 4; ++frame) write_frame(scratch / ("in." + std::to_string(frame) + ".exr"), frame);
  const std::string args = "--input " + scratch / "in.%d.exr" + " --frames 1-4" + kGain + " --out " +
                           scratch / "out.%d.exr" + " --out " + scratch / "out.%d.png" + " --json";
  REQUIRE(pfx_render(args).exit_code == 0);
  const std::string frame2 = read_bytes(scratch / "out.2.exr");
  struct stat before {};
  REQUIRE(::stat((scratch / "out.1.exr").c_str(), &before) == 0);
  fs::remove(scratch / "out.2.exr");
  fs::remove(scratch / "out.3.png");
  // Outputs are renamed into place only when complete, so existence is what marks a frame done;
  // a file something else cut short is not read and counts as done (--overwrite renders it).
  const std::string frame4 = read_bytes(scratch / "out.4.exr");
  std::ofstream(scratch / "out.4.exr", std::ios::binary | std::ios::trunc) << frame4.substr(0, frame4.size() / 2);

  Result r = pfx_render(args);
  CHECK(r.exit_code == 0);
  CHECK(statuses(json_lines(r.out)) == "1:skipped 2:rendered 3:rendered 4:skipped ");
  CHECK(read_bytes(scratch / "out.2.exr") == frame2);
  CHECK(fs::exists(scratch / "out.3.png"));
  CHECK(read_bytes(scratch / "out.4.exr").size() == frame4.size() / 2);
  struct stat after {};
  REQUIRE(::stat((scratch / "out.1.exr").c_str(), &after) == 0);
  CHECK(after.st_ino == before.st_ino);  // a skipped frame's file is not even replaced

  r = pfx_render(args + " --overwrite");
  CHECK(r.exit_code == 0);
  CHECK(statuses(json_lines(r.out)) == "1:rendered 2:rendered 3:rendered 4:rendered ");
  CHECK(read_bytes(scratch / "out.4.exr") == frame4);
}

TEST_CASE("pfx-render --print-frames gives each frame's files, chunk and done as a run sees them, and "
          "--chunk-index renders that chunk alone",
          "[render][sequence]") {
  Scratch scratch;
  for (int frame = 1; frame <= 7; ++frame) write_frame(scratch / ("in." + std::to_string(frame) + ".exr"), frame);
  const std::string files = "--input " + scratch / "in.%d.exr" + " --out " + scratch / "out.####.exr" +
                            " --report " + scratch / "r.%03d.json" + kGain;
  // 1-7 in chunks of 3: {1,2,3} {4,5,6} {7}. Render the middle one only.
  Result r = pfx_render(files + " --frames 1-7 --chunk 3 --chunk-index 1 --json");
  REQUIRE(r.exit_code == 0);
  CHECK(statuses(json_lines(r.out)) == "4:rendered 5:rendered 6:rendered ");
  for (int frame = 1; frame <= 7; ++frame)
    CHECK(fs::exists(scratch / ("out.000" + std::to_string(frame) + ".exr")) == (frame >= 4 && frame <= 6));

  r = pfx_render(files + " --frames 1-7 --chunk 3 --print-frames");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json plan = nlohmann::json::parse(r.out);
  CHECK(plan["chunks"] == 3);
  REQUIRE(plan["frames"].size() == 7);
  for (int frame = 1; frame <= 7; ++frame) {
    const nlohmann::json& entry = plan["frames"][frame - 1];
    INFO(entry.dump());
    CHECK(entry["frame"] == frame);
    CHECK(entry["chunk"] == (frame - 1) / 3);
    CHECK(entry["input"] == scratch / ("in." + std::to_string(frame) + ".exr"));
    CHECK(entry["outputs"] == nlohmann::json::array({scratch / ("out.000" + std::to_string(frame) + ".exr")}));
    CHECK(entry["report"] == scratch / ("r.00" + std::to_string(frame) + ".json"));
    CHECK(entry["done"] == (frame >= 4 && frame <= 6));
  }
  // The run skips exactly the frames the plan calls done.
  r = pfx_render(files + " --frames 1-7 --json");
  CHECK(r.exit_code == 0);
  CHECK(statuses(json_lines(r.out)) == "1:rendered 2:rendered 3:rendered 4:skipped 5:skipped 6:skipped 7:rendered ");

  // A stepped range is chunked by its frames, not its numbers: 1-7x2 is 1 3 5 7, chunk 1 of 3 is 7.
  r = pfx_render(files + " --frames 1-7x2 --chunk 3 --chunk-index 1 --print-frames");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json stepped = nlohmann::json::parse(r.out);
  CHECK(stepped["chunks"] == 2);
  REQUIRE(stepped["frames"].size() == 1);
  CHECK(stepped["frames"][0]["frame"] == 7);
  CHECK(stepped["frames"][0]["chunk"] == 1);
  CHECK(stepped["frames"][0]["done"] == true);
}

TEST_CASE("pfx-render --frames stops after a whole frame on SIGTERM (exit 143) and a rerun finishes the rest",
          "[render][sequence][hard]") {
  Scratch scratch;
  constexpr int kFrames = 300;
  write_frame(scratch / "in.1.exr", 1);
  for (int frame = 2; frame <= kFrames; ++frame)
    fs::copy_file(scratch / "in.1.exr", scratch / ("in." + std::to_string(frame) + ".exr"));
  const std::string args = std::string(PFX_RENDER) + " --plugins " PFX_TEST_PLUGIN_DIR " --input " +
                           scratch / "in.%d.exr" + " --frames 1-" + std::to_string(kFrames) + kGain + " --out " +
                           scratch / "out.%d.exr";
  // The shell waits for the first frame, sends SIGTERM and prints pfx-render's exit code.
  const std::string script = args + " 2>" + scratch / "err.txt" + " & pid=$!; while [ ! -e " +
                             scratch / "out.1.exr" + " ]; do sleep 0.01; done; kill -TERM $pid; wait $pid; echo $? >" +
                             scratch / "code.txt";
  REQUIRE(std::system(("sh -c '" + script + "'").c_str()) == 0);
  CHECK(read_bytes(scratch / "code.txt") == "143\n");
  const std::string err = read_bytes(scratch / "err.txt");
  INFO(err);
  CHECK(err.find("stopped by signal 15 (run the same command again to finish)") != std::string::npos);
  int written = 0;
  for (int frame = 1; frame <= kFrames; ++frame) {
    const std::string path = scratch / ("out." + std::to_string(frame) + ".exr");
    if (!fs::exists(path)) continue;
    ++written;
    pfx::app::Image image;
    std::string error;
    CHECK(pfx::app::read_exr(path, &image, &error));
  }
  CHECK(written < kFrames);
  for (const auto& name : scratch.files()) CHECK(name.find(".tmp-") == std::string::npos);

  const Result rerun = pfx_render(args.substr(args.find(" --input")) + " --json");
  CHECK(rerun.exit_code == 0);
  const auto summary = json_lines(rerun.out).back()["summary"];
  CHECK(summary["skipped"] == written);
  CHECK(summary["rendered"] == kFrames - written);
}
