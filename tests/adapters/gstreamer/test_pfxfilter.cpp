// pfxfilter in GStreamer pipelines, headless (EGL device platform): pfx-render's frame within one
// code, 10-bit frames, frames no pass would change handed on untouched, a property changed while
// the pipeline plays, GStreamer's GL state left for the next GL element, bad settings and a GLES context refused by name, the pipeline running to
// its end.
#include <catch2/catch.hpp>

#include "host_programs.hpp"
#include "render_process.hpp"

using pfx::test::gst_launch;
using pfx::test::pfx_render;
using pfx::test::read_bytes;
using pfx::test::read_rgba;
using pfx::test::run_host;
using pfx::test::RunResult;
using pfx::test::Scratch;

namespace {

// testsrc frames of 64x48 RGBA into GL, through `middle`, back out to a raw file.
std::string gl_pipeline(int frames, const std::string& middle, const std::string& out,
                        const std::string& format = "RGBA") {
  return "videotestsrc num-buffers=" + std::to_string(frames) + " pattern=smpte ! video/x-raw,format=" + format +
         ",width=64,height=48,framerate=25/1 ! glupload ! " + middle + " gldownload ! video/x-raw,format=" + format +
         " ! filesink location=" + out;
}

}  // namespace

TEST_CASE("pfxfilter: bloom on GStreamer's context is pfx-render's frame within one code, testsrc2 and a photograph",
          "[adapters][gstreamer][pfxfilter]") {
  Scratch scratch;
  const std::string frame = scratch / "testsrc2.png";
  REQUIRE(run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-f", "lavfi", "-i",
                    "testsrc2=size=160x120:rate=25", "-frames:v", "1", "-update", "1", "-y", frame})
              .exit_code == 0);
  for (const std::string& in : {frame, std::string(PFX_TEST_PHOTOGRAPH)}) {
    INFO(in);
    RunResult r = gst_launch("filesrc location=" + in + " ! pngdec ! videoconvert ! video/x-raw,format=RGBA ! glupload ! "
                             "pfxfilter chain=bloom set=bloom.threshold=0.5 ! gldownload ! video/x-raw,format=RGBA ! "
                             "pngenc ! filesink location=" + scratch / "gl.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    auto rendered = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + in +
                                   " --chain bloom --set bloom.threshold=0.5 --out " + scratch / "pfx-render.png",
                               false);
    REQUIRE(rendered.exit_code == 0);
    const auto host = read_rgba(scratch / "gl.png"), reference = read_rgba(scratch / "pfx-render.png"),
               input = read_rgba(in);
    REQUIRE(host.pixels.size() == reference.pixels.size());
    int worst = 0;
    for (size_t i = 0; i < host.pixels.size(); ++i) worst = std::max(worst, std::abs(host.pixels[i] - reference.pixels[i]));
    CHECK(worst <= 1);
    CHECK(host.pixels != input.pixels);
  }
}

TEST_CASE("pfxfilter: 10-bit RGB10A2 frames come back unchanged with no effect and bloom with bloom",
          "[adapters][gstreamer][pfxfilter]") {
  Scratch scratch;
  REQUIRE(gst_launch(gl_pipeline(2, "", scratch / "plain.raw", "RGB10A2_LE")).exit_code == 0);
  RunResult r = gst_launch(gl_pipeline(2, "pfxfilter chain=none !", scratch / "none.raw", "RGB10A2_LE"));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  r = gst_launch(gl_pipeline(2, "pfxfilter chain=bloom !", scratch / "bloom.raw", "RGB10A2_LE"));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto plain = read_bytes(scratch / "plain.raw");
  REQUIRE(plain.size() == 2 * 64 * 48 * 4);
  CHECK(read_bytes(scratch / "none.raw") == plain);  // every 10-bit code through half float and back
  CHECK(read_bytes(scratch / "bloom.raw") != plain);
}

TEST_CASE("pfxfilter: a property changed while the pipeline plays applies from the next frame",
          "[adapters][gstreamer][pfxfilter]") {
  Scratch scratch;
  const std::string changed = scratch / "changed.rgba", bloom = scratch / "bloom.rgba", none = scratch / "none.rgba";
  RunResult r = run_host({PFX_GST_PROBE, gl_pipeline(6, "pfxfilter name=fx chain=none !", changed), "--set", "3", "chain",
                          "bloom", "--set", "4", "set", "bloom.strength=0"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  REQUIRE(gst_launch(gl_pipeline(6, "pfxfilter chain=bloom !", bloom)).exit_code == 0);
  REQUIRE(gst_launch(gl_pipeline(6, "pfxfilter chain=none !", none)).exit_code == 0);
  const size_t frame = 64 * 48 * 4;
  const auto a = read_bytes(changed), b = read_bytes(bloom), c = read_bytes(none);
  REQUIRE(a.size() == 6 * frame);
  auto same = [&](const std::vector<uint8_t>& x, const std::vector<uint8_t>& y, int n) {
    return std::equal(x.begin() + n * frame, x.begin() + (n + 1) * frame, y.begin() + n * frame);
  };
  for (int n = 0; n < 3; ++n) CHECK(same(a, c, n));  // none
  CHECK(same(a, b, 3));                              // bloom from frame 3
  CHECK(!same(a, c, 3));
  for (int n = 4; n < 6; ++n) CHECK(same(a, c, n));  // strength 0 from frame 4: nothing added
}

TEST_CASE("pfxfilter: with no effect on, or only no-ops, each buffer is handed on as it came, and a chain that runs draws "
          "a new one",
          "[adapters][gstreamer][pfxfilter]") {
  Scratch scratch;
  // Frames 0-2 no effect, 3 bloom, 4-5 bloom at strength 0 (it declares no pass).
  RunResult r = run_host({PFX_GST_PROBE, gl_pipeline(6, "pfxfilter name=fx chain=none !", scratch / "out.rgba"),
                          "--set", "3", "chain", "bloom", "--set", "4", "set", "bloom.strength=0"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("buffers 6\n") != std::string::npos);
  CHECK(r.output.find("handed on as they came: 0,1,2,4,5\n") != std::string::npos);
  // Settings that do not build pass the frames through the same way.
  r = run_host({PFX_GST_PROBE, gl_pipeline(2, "pfxfilter name=fx chain=nosuch !", scratch / "bad.rgba")});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("handed on as they came: 0,1\n") != std::string::npos);
}

TEST_CASE("pfxfilter leaves GStreamer's GL state as it found it: the GL element after it draws the same picture",
          "[adapters][gstreamer][pfxfilter]") {
  Scratch scratch;
  for (const std::string next : {"gleffects effect=glow", "gltransformation rotation-z=20 scale-x=0.8"}) {
    INFO(next);
    REQUIRE(gst_launch(gl_pipeline(2, next + " !", scratch / "alone.rgba")).exit_code == 0);
    RunResult r = gst_launch(gl_pipeline(2, "pfxfilter chain=none ! " + next + " !", scratch / "after.rgba"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_bytes(scratch / "after.rgba") == read_bytes(scratch / "alone.rgba"));
  }
}

TEST_CASE("pfxfilter: bad settings pass frames through with a warning naming the reason, and the pipeline ends normally",
          "[adapters][gstreamer][pfxfilter][errors]") {
  Scratch scratch;
  REQUIRE(gst_launch(gl_pipeline(3, "", scratch / "plain.rgba")).exit_code == 0);
  const auto plain = read_bytes(scratch / "plain.rgba");
  const std::pair<std::string, std::string> cases[] = {
      {"chain=nosuch", "effect 'nosuch' is not loaded"},
      {"set=garbage", "garbage"},
      {"set=bloom.threshold=abc", "bloom.threshold"},
      {"transfer=gamma", "transfer 'gamma'"},
      {"preset=" + scratch / "missing.json", scratch / "missing.json"},
  };
  for (const auto& [setting, reason] : cases) {
    INFO(setting);
    // Without -q: gst-launch prints the element's warnings.
    RunResult r = gst_launch(gl_pipeline(3, "pfxfilter " + setting + " !", scratch / "out.rgba"), false);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(read_bytes(scratch / "out.rgba") == plain);
    CHECK(r.output.find(reason) != std::string::npos);
    CHECK(pfx::test::occurrences(r.output, "frames pass through unchanged") == 1);
  }
}

TEST_CASE("pfxfilter refuses a GLES context with an element error naming the reason, without crashing",
          "[adapters][gstreamer][pfxfilter][errors]") {
  Scratch scratch;
  RunResult r = gst_launch(gl_pipeline(3, "pfxfilter !", scratch / "out.rgba"), false, {"GST_GL_API=gles2"});
  INFO(r.output);
  CHECK(r.exit_code == 1);  // gst-launch's error exit, not a signal
  CHECK(r.output.find("ERROR: from element /GstPipeline:pipeline0/GstPfxFilter:pfxfilter0: pfxfilter: GStreamer's GL "
                      "context is OpenGL ES") != std::string::npos);
  CHECK(r.output.find("pfx needs desktop OpenGL 4.5") != std::string::npos);
}

TEST_CASE("pfxfilter refuses a desktop context below OpenGL 4.5 with an element error naming the version",
          "[adapters][gstreamer][pfxfilter][errors]") {
  Scratch scratch;
  // Mesa reports the version it is told to; the element must read it and refuse, not load 4.5
  // functions the context does not promise.
  RunResult r = gst_launch(gl_pipeline(3, "pfxfilter !", scratch / "out.rgba"), false, {"MESA_GL_VERSION_OVERRIDE=3.3"});
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("ERROR: from element /GstPipeline:pipeline0/GstPfxFilter:pfxfilter0: pfxfilter: GStreamer's GL "
                      "context is OpenGL 3.3: pfx needs OpenGL 4.5") != std::string::npos);
}
