// pfxfilter held under load: a 2,000-frame pipeline does not grow the application, and two
// pfxfilter instances in the branches of a tee (two streaming threads) give the frames of one.
#include <catch2/catch.hpp>

#include <sstream>

#include "host_programs.hpp"
#include "memory_watch.hpp"
#include "render_process.hpp"

using pfx::test::Scratch;

TEST_CASE("pfxfilter: 2,000 frames leave the application's resident memory where it was at frame 200",
          "[adapters][gstreamer][pfxfilter][load]") {
  pfx::test::use_small_pages();
  auto r = pfx::test::run_host({PFX_GST_PROBE,
                                "videotestsrc num-buffers=2100 ! video/x-raw,format=RGBA,width=64,height=48 ! glupload ! "
                                "pfxfilter name=fx chain=bloom ! gldownload ! fakesink",
                                "--rss", "200", "--rss", "2000"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::istringstream lines(r.output);
  std::string word;
  long frame = 0;
  uint64_t bytes = 0, early = 0, late = 0;
  while (lines >> word)
    if (word == "rss" && lines >> frame >> bytes) (frame == 200 ? early : late) = bytes;
  REQUIRE(early > 0);
  REQUIRE(late > 0);
  CHECK(late <= early + pfx::test::kLoadGrowthLimit);
}

TEST_CASE("pfxfilter: two instances in the branches of a tee give the frames of one",
          "[adapters][gstreamer][pfxfilter][load]") {
  Scratch scratch;
  const std::string source =
      "videotestsrc num-buffers=5 pattern=smpte ! video/x-raw,format=RGBA,width=64,height=48,framerate=25/1";
  const std::string branch =
      "queue ! glupload ! pfxfilter chain=bloom set=bloom.threshold=0.5 ! gldownload ! video/x-raw,format=RGBA ! "
      "filesink location=";
  auto run = [&](const std::string& pipeline) {
    auto r = pfx::test::run_host({PFX_GST_PROBE, pipeline});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
  };
  using pfx::test::read_bytes;
  run(source + " ! " + branch + scratch / "one.rgba");
  run(source + " ! tee name=t t. ! " + branch + scratch / "a.rgba" + " t. ! " + branch + scratch / "b.rgba");
  const auto one = read_bytes(scratch / "one.rgba");
  REQUIRE(one.size() == 5 * 64 * 48 * 4);
  CHECK(read_bytes(scratch / "a.rgba") == one);
  CHECK(read_bytes(scratch / "b.rgba") == one);
}
