// ffmpeg held under load: a 2,000-frame clip through pfx_chain does not grow the process, and
// GStreamer's frei0r bridge with two instances on two streaming threads (a tee) gives each
// branch the frames one instance gives.
#include <catch2/catch.hpp>

#include "host_programs.hpp"
#include "memory_watch.hpp"
#include "render_process.hpp"

using pfx::test::Scratch;

TEST_CASE("ffmpeg: 2,000 frames through pfx_chain leave resident memory where it was at frame 200",
          "[adapters][frei0r][ffmpeg][load]") {
  pfx::test::use_small_pages();
  pfx::test::ViewerProcess ffmpeg(pfx::test::host_command(
      {PFX_FFMPEG, "-hide_banner", "-loglevel", "warning", "-nostats", "-f", "lavfi", "-i", "testsrc2=size=64x48:rate=25",
       "-frames:v", "2100", "-vf", "frei0r=filter_name=pfx_chain:filter_params=bloom", "-progress", "pipe:1",
       "-stats_period", "0.02", "-f", "null", "-"}));
  uint64_t early = 0, late = 0;
  long early_frame = 0, late_frame = 0;
  while (!late) {
    const std::string line = ffmpeg.wait_for_line("frame=", 120);
    INFO(ffmpeg.output());
    REQUIRE(!line.empty());
    const long frame = std::stol(line.substr(line.find('=') + 1));
    if (frame >= 200 && !early) early = pfx::test::anonymous_bytes(ffmpeg.pid()), early_frame = frame;
    if (frame >= 2000) late = pfx::test::anonymous_bytes(ffmpeg.pid()), late_frame = frame;
  }
  REQUIRE(ffmpeg.wait_exit(120) == 0);
  INFO("RssAnon " << early << " bytes at frame " << early_frame << ", " << late << " at frame " << late_frame);
  REQUIRE(early > 0);
  CHECK(late <= early + pfx::test::kLoadGrowthLimit);
}

TEST_CASE("GStreamer's frei0r bridge: two instances on two streaming threads (tee) give the frames of one",
          "[adapters][frei0r][gstreamer][load]") {
  Scratch scratch;
  const std::string source =
      "videotestsrc num-buffers=5 pattern=smpte ! video/x-raw,format=RGBA,width=64,height=48,framerate=25/1";
  auto run = [&](const std::string& pipeline) {
    auto r = pfx::test::gst_launch(pipeline);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
  };
  using pfx::test::read_bytes;
  const std::string branch = "queue ! frei0r-filter-pfx-chain chain=bloom set=bloom.threshold=0.5 ! filesink location=";
  run(source + " ! " + branch + scratch / "one.rgba");
  run(source + " ! tee name=t t. ! " + branch + scratch / "a.rgba" + " t. ! " + branch + scratch / "b.rgba");
  const auto one = read_bytes(scratch / "one.rgba");
  REQUIRE(one.size() == 5 * 64 * 48 * 4);
  CHECK(read_bytes(scratch / "a.rgba") == one);
  CHECK(read_bytes(scratch / "b.rgba") == one);
}
