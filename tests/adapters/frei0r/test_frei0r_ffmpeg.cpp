// The frei0r plugins in Debian's ffmpeg, run as a user runs it: pfx_chain gives pfx-render's bytes
// on a testsrc2 frame (two sizes, one odd) and on a real photograph, the frame time reaches the
// chain, frames come out the right way up, and every bad setting passes frames through with one
// line on stderr while ffmpeg runs to its end.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "host_programs.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::read_rgba;
using pfx::test::rgb_of;
using pfx::test::run_host;
using pfx::test::RunResult;
using pfx::test::Scratch;

namespace {

// One frame of ffmpeg's own test pattern, as a PNG.
std::string testsrc_frame(const Scratch& scratch, const std::string& size) {
  const std::string path = scratch / ("testsrc2-" + size + ".png");
  RunResult r = run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-f", "lavfi", "-i",
                          "testsrc2=size=" + size + ":rate=25", "-frames:v", "1", "-update", "1", "-y", path});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  return path;
}

// ffmpeg -i in -vf FILTER out.png, one frame.
RunResult ffmpeg_filter(const std::string& in, const std::string& filter, const std::string& out,
                        const std::vector<std::string>& environment = {}) {
  return run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "warning", "-i", in, "-vf", filter, "-frames:v", "1",
                   "-update", "1", "-y", out},
                  environment);
}

// The raw RGBA frames of a clip through a filter: ffmpeg's lavfi testsrc2, `frames` frames.
std::vector<uint8_t> filtered_clip(const Scratch& scratch, const std::string& size, int frames, const std::string& filter,
                                   RunResult* run, const std::vector<std::string>& environment = {}) {
  const std::string out = scratch / "clip.rgba";
  std::vector<std::string> argv = {PFX_FFMPEG, "-hide_banner", "-loglevel", "warning", "-f", "lavfi", "-i",
                                   "testsrc2=size=" + size + ":rate=25", "-frames:v", std::to_string(frames)};
  if (!filter.empty()) argv.insert(argv.end(), {"-vf", filter});
  argv.insert(argv.end(), {"-f", "rawvideo", "-pix_fmt", "rgba", "-y", out});
  *run = run_host(argv, environment);
  std::ifstream file(out, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(file), {});
}

}  // namespace

TEST_CASE("ffmpeg: pfx_chain with bloom at threshold 0.5 gives pfx-render's bytes, on testsrc2 and a photograph",
          "[adapters][frei0r][ffmpeg]") {
  Scratch scratch;
  const std::vector<std::string> inputs = {testsrc_frame(scratch, "160x120"), testsrc_frame(scratch, "161x97"),
                                           PFX_TEST_PHOTOGRAPH};
  for (const auto& in : inputs) {
    INFO(in);
    RunResult r = ffmpeg_filter(in, "frei0r=filter_name=pfx_chain:filter_params=bloom|bloom.threshold=0.5",
                                scratch / "ffmpeg.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    auto rendered = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + in +
                                   " --chain bloom --set bloom.threshold=0.5 --out " + scratch / "pfx-render.png",
                               false);
    INFO(rendered.err);
    REQUIRE(rendered.exit_code == 0);
    const auto input = read_rgba(in), host = read_rgba(scratch / "ffmpeg.png"),
               reference = read_rgba(scratch / "pfx-render.png");
    REQUIRE(host.width == input.width);
    REQUIRE(host.height == input.height);
    CHECK(host.pixels == reference.pixels);
    CHECK(rgb_of(host) != rgb_of(input));  // the bloom shows
  }
}

TEST_CASE("ffmpeg: frames of a clip reach the chain with ffmpeg's time, in milliseconds, and their index",
          "[adapters][frei0r][ffmpeg]") {
  Scratch scratch;
  RunResult run;
  // 64 pixels wide: for frames whose rows ffmpeg 5.1 has to repack for frei0r (32 wide, 160
  // wide) it hands over a copy without the frame's timestamp, and the time is garbage.
  const auto clip = filtered_clip(scratch, "64x48", 6, "frei0r=filter_name=pfx_chain:filter_params=clock||linear", &run);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const size_t frame_bytes = 64 * 48 * 4;
  REQUIRE(clip.size() == 6 * frame_bytes);
  for (int n = 0; n < 6; ++n) {
    INFO("frame " << n);
    const uint8_t* pixel = &clip[n * frame_bytes + (10 * 64 + 7) * 4];
    // ffmpeg hands frei0r pts * time_base * 1000: frame n of 25 fps is at 40 n "seconds".
    CHECK(int(pixel[0]) == 0);
    CHECK(int(pixel[1]) == (40 * n) % 256);
    CHECK(int(pixel[2]) == n + 1);  // the instance's frame count
    CHECK(int(pixel[3]) == 255);
  }
}

TEST_CASE("ffmpeg: the chain sees frames the right way up, as pfx-render does", "[adapters][frei0r][ffmpeg]") {
  Scratch scratch;
  const std::string in = testsrc_frame(scratch, "64x48");
  RunResult r = ffmpeg_filter(in, "frei0r=filter_name=pfx_chain:filter_params=ramp||linear", scratch / "ramp.png");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto ramp = read_rgba(scratch / "ramp.png");
  // Row 0 of the file is the picture's top: GL's highest row, (y + 0.5) / h near 1.
  CHECK(int(ramp.pixels[1]) == 252);                          // round(255 * 47.5 / 48)
  CHECK(int(ramp.pixels[(47 * 64) * 4 + 1]) == 3);            // the bottom row
  CHECK(int(ramp.pixels[(47 * 64 + 63) * 4 + 0]) == 253);     // x runs left to right
  auto rendered = pfx_render("--plugins " PFX_ADAPTER_TEST_PLUGIN_DIR " --input " + in +
                                 " --chain ramp --transfer linear --out " + scratch / "pfx-render.png",
                             false);
  REQUIRE(rendered.exit_code == 0);
  CHECK(read_rgba(scratch / "pfx-render.png").pixels == ramp.pixels);
}

TEST_CASE("ffmpeg: every bad setting passes frames through, says why once, and ffmpeg runs to its end",
          "[adapters][frei0r][ffmpeg][errors]") {
  Scratch scratch;
  RunResult plain;
  const auto original = filtered_clip(scratch, "32x24", 4, "", &plain);
  REQUIRE(plain.exit_code == 0);
  REQUIRE(original.size() == 4 * 32 * 24 * 4);
  std::ofstream(scratch / "broken.json") << "{\"pfx_preset\": 1, \"chain\": [";
  struct Case {
    std::string params, reason;
    std::vector<std::string> environment;
  };
  const Case cases[] = {
      {"nosuch", "effect 'nosuch' is not loaded", {}},
      {"bloom|garbage", "garbage", {}},
      {"bloom|bloom.nosuch=1", "nosuch", {}},
      {"bloom|bloom.threshold=abc", "bloom.threshold", {}},
      {"bloom||gamma", "transfer 'gamma': expected srgb or linear", {}},
      {"bloom|||" + scratch / "missing.json", scratch / "missing.json", {}},
      {"|||" + scratch / "broken.json", scratch / "broken.json", {}},
      {"bloom", "surfaceless", {"__EGL_VENDOR_LIBRARY_FILENAMES=" + scratch / "no-such-vendor.json"}},
  };
  for (const auto& c : cases) {
    INFO(c.params);
    RunResult run;
    const auto frames =
        filtered_clip(scratch, "32x24", 4, "frei0r=filter_name=pfx_chain:filter_params=" + c.params, &run, c.environment);
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK(frames == original);
    CHECK(run.output.find(c.reason) != std::string::npos);
    CHECK(pfx::test::occurrences(run.output, "frames pass through unchanged") == 1);
  }
}

TEST_CASE("ffmpeg: a per-effect plugin whose effect is missing passes frames through and says so",
          "[adapters][frei0r][ffmpeg][errors]") {
  Scratch scratch;
  const std::string folder = scratch / "frei0r";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(PFX_FREI0R_DIR "/pfx_chain.so", folder + "/pfx_nosuch.so");
  RunResult plain;
  const auto original = filtered_clip(scratch, "32x24", 3, "", &plain);
  RunResult run;
  // libpfxhost is found beside the build's frei0r folder, not beside this copy.
  const std::string libraries = std::filesystem::path(PFX_FREI0R_DIR).parent_path().string();
  const auto frames = filtered_clip(scratch, "32x24", 3, "frei0r=filter_name=pfx_nosuch", &run,
                                    {"FREI0R_PATH=" + folder, "LD_LIBRARY_PATH=" + libraries});
  INFO(run.output);
  CHECK(run.exit_code == 0);
  CHECK(frames == original);
  CHECK(run.output.find("the pfx effect 'nosuch' is not among the plugins loaded") != std::string::npos);
}

TEST_CASE("ffmpeg: a width that is not a multiple of 16 runs right through docs/hosts.md's pad-and-crop recipe",
          "[adapters][frei0r][ffmpeg]") {
  // ffmpeg 5.1 hands frei0r rows padded to 64 bytes: a 644-pixel-wide frame arrives with 656
  // pixels a row and comes out scrambled. The recipe pads the frame to a width of a multiple of 16
  // before the filter and crops it back after, in one -vf; the chain then sees the padded frame
  // (black columns at the right), so the reference is pfx-render's run over that padded frame.
  Scratch scratch;
  const std::string photo = scratch / "photo-644x483.png";
  RunResult made = run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-i", PFX_TEST_PHOTOGRAPH, "-vf",
                             "scale=644:483", "-frames:v", "1", "-update", "1", "-y", photo});
  INFO(made.output);
  REQUIRE(made.exit_code == 0);
  RunResult r = ffmpeg_filter(
      photo, "pad=ceil(iw/16)*16:ih,frei0r=filter_name=pfx_chain:filter_params=bloom|bloom.threshold=0.5,crop=644:ih:0:0",
      scratch / "ffmpeg.png");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string padded = scratch / "padded.png";
  made = run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-i", photo, "-vf", "pad=656:ih", "-frames:v", "1",
                   "-update", "1", "-y", padded});
  REQUIRE(made.exit_code == 0);
  auto rendered = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + padded +
                                 " --chain bloom --set bloom.threshold=0.5 --out " + scratch / "pfx-render.png",
                             false);
  INFO(rendered.err);
  REQUIRE(rendered.exit_code == 0);
  const auto input = read_rgba(photo), host = read_rgba(scratch / "ffmpeg.png"),
             reference = read_rgba(scratch / "pfx-render.png");
  REQUIRE(host.width == 644);
  REQUIRE(host.height == 483);
  REQUIRE(reference.width == 656);
  size_t differing = 0;
  for (int y = 0; y < 483; ++y)
    for (int x = 0; x < 644 * 4; ++x)
      differing += host.pixels[(y * 644) * 4 + x] != reference.pixels[(y * 656) * 4 + x];
  CHECK(differing == 0);
  CHECK(rgb_of(host) != rgb_of(input));  // the bloom shows
}
