// The same frei0r plugins in melt (MLT, under Kdenlive and Shotcut) and in GStreamer's frei0r
// bridge: the same bytes as ffmpeg and pfx-render, the per-effect plugins' named parameters,
// the frame time each host passes (seconds), and bad settings passing frames through.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "host_programs.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::read_bytes;
using pfx::test::read_rgba;
using pfx::test::run_host;
using pfx::test::RunResult;
using pfx::test::Scratch;

namespace {

// A square-pixel progressive MLT profile of the frame's size at 25 fps, so melt scales nothing.
std::string square_profile(const Scratch& scratch, int width, int height) {
  const std::string path = scratch / ("square-" + std::to_string(width) + "x" + std::to_string(height) + ".profile");
  std::ofstream(path) << "description=square pixels\nframe_rate_num=25\nframe_rate_den=1\nwidth=" << width
                      << "\nheight=" << height << "\nprogressive=1\nsample_aspect_num=1\nsample_aspect_den=1\n"
                      << "display_aspect_num=" << width << "\ndisplay_aspect_den=" << height << "\ncolorspace=709\n";
  return path;
}

// melt PRODUCER -filter frei0r.NAME PROPERTIES... into one RGBA PNG, with MLT's image format RGBA
// throughout (no conversion the filter could be blamed for).
RunResult melt_frame(const Scratch& scratch, const std::string& in, int width, int height,
                     const std::vector<std::string>& filter, const std::string& out) {
  // MLT's avformat producer reads the PNG (its default for pictures, gdk-pixbuf, deadlocks in
  // glibc's locale lock when AddressSanitizer's runtime is preloaded, as the sanitizer pass does).
  std::vector<std::string> argv = {PFX_MELT, "-quiet", "-profile", square_profile(scratch, width, height),
                                   "avformat:" + in, "out=0", "-filter"};
  argv.insert(argv.end(), filter.begin(), filter.end());
  // real_time=0: MLT's consumers drop frames that come late by default, and on a loaded machine the
  // one frame asked for can be one of them; every frame is rendered in turn without it.
  argv.insert(argv.end(), {"-consumer", "avformat:" + out, "vcodec=png", "pix_fmt=rgba", "mlt_image_format=rgba",
                           "update=1", "real_time=0"});
  return run_host(argv);
}

// gst-launch-1.0: a PNG through an element into a PNG.
RunResult gst_frame(const std::string& in, const std::vector<std::string>& element, const std::string& out) {
  std::vector<std::string> argv = {PFX_GST_LAUNCH, "-q", "filesrc", "location=" + in, "!", "pngdec", "!", "videoconvert",
                                   "!", "video/x-raw,format=RGBA", "!"};
  argv.insert(argv.end(), element.begin(), element.end());
  argv.insert(argv.end(), {"!", "pngenc", "!", "filesink", "location=" + out});
  return run_host(argv);
}

// The frames of ffmpeg's testsrc2 (64x48, 25 fps) as a lossless clip melt can read.
std::string test_clip(const Scratch& scratch, int frames) {
  const std::string path = scratch / "clip.mkv";
  RunResult r = run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-f", "lavfi", "-i",
                          "testsrc2=size=64x48:rate=25", "-frames:v", std::to_string(frames), "-c:v", "ffv1", "-y", path});
  REQUIRE(r.exit_code == 0);
  return path;
}

struct Reference {
  std::string in;
  int width, height;
  std::vector<uint8_t> pixels;  // pfx-render's --chain bloom --set bloom.threshold=0.5, RGBA
};

// A testsrc2 frame and the photograph, with what pfx-render (and so ffmpeg) makes of them.
std::vector<Reference> references(const Scratch& scratch) {
  const std::string frame = scratch / "testsrc2.png";
  REQUIRE(run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-f", "lavfi", "-i",
                    "testsrc2=size=160x120:rate=25", "-frames:v", "1", "-update", "1", "-y", frame})
              .exit_code == 0);
  std::vector<Reference> list;
  for (const std::string& in : {frame, std::string(PFX_TEST_PHOTOGRAPH)}) {
    auto r = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + in + " --chain bloom --set bloom.threshold=0.5 "
                        "--out " + scratch / "reference.png", false);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto image = read_rgba(scratch / "reference.png");
    list.push_back({in, image.width, image.height, image.pixels});
  }
  return list;
}

}  // namespace

TEST_CASE("melt: frei0r.pfx_chain and frei0r.pfx_bloom give pfx-render's (and ffmpeg's) bytes",
          "[adapters][frei0r][melt]") {
  Scratch scratch;
  for (const auto& reference : references(scratch)) {
    INFO(reference.in);
    // MLT reads a string holding '=' or ';' as keyframes unless it is quoted; on melt's command
    // line the quotes are doubled (docs/hosts.md).
    RunResult r = melt_frame(scratch, reference.in, reference.width, reference.height,
                             {"frei0r.pfx_chain", "chain=bloom", "set=\"\"bloom.threshold=0.5\"\""}, scratch / "chain.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_rgba(scratch / "chain.png").pixels == reference.pixels);
    // pfx_bloom's threshold slider: 0-1 over 0-8, so 0.0625 is 0.5.
    r = melt_frame(scratch, reference.in, reference.width, reference.height, {"frei0r.pfx_bloom", "threshold=0.0625"},
                   scratch / "bloom.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_rgba(scratch / "bloom.png").pixels == reference.pixels);
  }
}

TEST_CASE("GStreamer's frei0r bridge: frei0r-filter-pfx-chain and -pfx-bloom give pfx-render's bytes",
          "[adapters][frei0r][gstreamer]") {
  Scratch scratch;
  for (const auto& reference : references(scratch)) {
    INFO(reference.in);
    RunResult r = gst_frame(reference.in, {"frei0r-filter-pfx-chain", "chain=bloom", "set=bloom.threshold=0.5"},
                            scratch / "chain.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_rgba(scratch / "chain.png").pixels == reference.pixels);
    r = gst_frame(reference.in, {"frei0r-filter-pfx-bloom", "threshold=0.0625"}, scratch / "bloom.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_rgba(scratch / "bloom.png").pixels == reference.pixels);
  }
}

TEST_CASE("melt and GStreamer's bridge pass the frame time in seconds", "[adapters][frei0r][melt][gstreamer]") {
  Scratch scratch;
  const std::string melt_out = scratch / "melt.rgba", gst_out = scratch / "gst.rgba";
  RunResult r = run_host({PFX_MELT, "-quiet", "-profile", square_profile(scratch, 64, 48), test_clip(scratch, 6),
                          "-filter", "frei0r.pfx_chain", "chain=clock", "transfer=linear", "-consumer",
                          "avformat:" + melt_out, "f=rawvideo", "pix_fmt=rgba", "mlt_image_format=rgba", "real_time=0"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  r = run_host({PFX_GST_LAUNCH, "-q", "videotestsrc", "num-buffers=6", "!",
                "video/x-raw,format=RGBA,width=64,height=48,framerate=25/1", "!", "frei0r-filter-pfx-chain", "chain=clock",
                "transfer=linear", "!", "filesink", "location=" + gst_out});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const auto& path : {melt_out, gst_out}) {
    INFO(path);
    const auto frames = read_bytes(path);
    const size_t frame_bytes = 64 * 48 * 4;
    REQUIRE(frames.size() == 6 * frame_bytes);
    for (int n = 0; n < 6; ++n) {
      INFO("frame " << n);
      const uint8_t* pixel = &frames[n * frame_bytes + (20 * 64 + 30) * 4];
      const double seconds = n / 25.0;  // R is the fraction of a second, G the whole seconds
      CHECK(int(pixel[0]) == int(std::lround(255 * seconds)));
      CHECK(int(pixel[1]) == 0);
      CHECK(int(pixel[2]) == n + 1);
    }
  }
}

TEST_CASE("melt and GStreamer's bridge run to their end with bad settings, frames unchanged, the reason said",
          "[adapters][frei0r][melt][gstreamer][errors]") {
  Scratch scratch;
  const std::string clip = test_clip(scratch, 3);
  struct Case {
    std::vector<std::string> melt, gst;
    std::string reason;
  };
  const Case cases[] = {
      {{"chain=nosuch"}, {"chain=nosuch"}, "effect 'nosuch' is not loaded"},
      {{"set=\"\"bloom.nosuch=1\"\""}, {"set=bloom.nosuch=1"}, "nosuch"},
      {{"transfer=gamma"}, {"transfer=gamma"}, "transfer 'gamma'"},
      {{"preset=" + scratch / "missing.json"}, {"preset=" + scratch / "missing.json"}, scratch / "missing.json"},
  };
  const std::string plain = scratch / "plain.rgba", out = scratch / "out.rgba";
  auto melt = [&](const std::vector<std::string>& properties, const std::string& file) {
    std::vector<std::string> argv = {PFX_MELT, "-quiet", "-profile", square_profile(scratch, 64, 48), clip};
    if (!properties.empty()) argv.insert(argv.end(), {"-filter", "frei0r.pfx_chain"});
    argv.insert(argv.end(), properties.begin(), properties.end());
    argv.insert(argv.end(),
                {"-consumer", "avformat:" + file, "f=rawvideo", "pix_fmt=rgba", "mlt_image_format=rgba", "real_time=0"});
    return run_host(argv);
  };
  auto gst = [&](const std::vector<std::string>& properties, const std::string& file) {
    std::vector<std::string> argv = {PFX_GST_LAUNCH, "-q", "videotestsrc", "num-buffers=3", "!",
                                     "video/x-raw,format=RGBA,width=64,height=48,framerate=25/1", "!"};
    argv.push_back(properties.empty() ? "identity" : "frei0r-filter-pfx-chain");
    argv.insert(argv.end(), properties.begin(), properties.end());
    argv.insert(argv.end(), {"!", "filesink", "location=" + file});
    return run_host(argv);
  };
  REQUIRE(melt({}, plain).exit_code == 0);
  const auto melt_plain = read_bytes(plain);
  REQUIRE(gst({}, plain).exit_code == 0);
  const auto gst_plain = read_bytes(plain);
  for (const auto& c : cases) {
    INFO(c.reason);
    RunResult r = melt(c.melt, out);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(read_bytes(out) == melt_plain);
    CHECK(r.output.find(c.reason) != std::string::npos);
    r = gst(c.gst, out);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(read_bytes(out) == gst_plain);
    CHECK(r.output.find(c.reason) != std::string::npos);
    CHECK(pfx::test::occurrences(r.output, "frames pass through unchanged") == 1);
  }
}
