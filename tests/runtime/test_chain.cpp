// The chain over real GL with the minimal fixture plugin: results against values computed here
// on the CPU, skipping of disabled and no-op effects, pooling, resizing and reports.
#include <catch2/catch.hpp>

#include <cmath>

#include <glad/gl.h>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

using pfx::app::Image;

namespace {

struct Rig {
  std::unique_ptr<pfx::host::PluginRegistry> registry = pfx::test::make_registry();
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  Rig() {
    std::string error;
    REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
  }
  void set(const std::string& assignment) {
    std::string error;
    INFO(error);
    REQUIRE(params.set_assignment(assignment, &error));
  }
  // Renders img through the chain; returns the output read back (row 0 = top).
  Image render(const Image& img, bool expect_ok = true, std::string* error_out = nullptr) {
    pfx::host::FrameTextures textures;
    textures.color = pfx::app::upload_color_texture(img);
    uint32_t output = pfx::app::create_color_texture(img.width, img.height);
    std::string error;
    bool ok = chain->render(pfx::test::make_frame(img.width, img.height), textures, output, &error);
    INFO(error);
    CHECK(ok == expect_ok);
    if (error_out) *error_out = error;
    Image result = pfx::app::download_color_texture(output, img.width, img.height);
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(output);
    return result;
  }
};

}  // namespace

TEST_CASE("gain multiplies every colour channel and keeps alpha", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("gain", &error));
  rig.set("gain.gain=2.5");
  Image input = pfx::test::test_image(37, 19);
  Image output = rig.render(input);
  for (size_t i = 0; i < input.rgba.size(); ++i) {
    // The value goes through two half conversions (upload, render target), and the GL may round
    // either one toward zero (llvmpipe does on upload): up to 2 half ulps, 2^-9 relative. A
    // gain off by 0.4% fails this.
    float expected = (i % 4 == 3) ? input.rgba[i] : input.rgba[i] * 2.5f;
    REQUIRE(output.rgba[i] == Approx(expected).epsilon(1.0 / 512).margin(1e-6));
  }
  REQUIRE(rig.chain->report().passes.size() == 1);
  CHECK(rig.chain->report().passes[0].effect == "gain");
  CHECK(rig.chain->report().peak_target_bytes == 0);  // it writes the chain output directly
}

TEST_CASE("disabled and no-op effects cost no pass and no target, and the output is the input", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("gain", &error));     // gain 1: a no-op
  REQUIRE(rig.chain->add("boxblur", &error));  // disabled below
  rig.set("boxblur.radius=3");
  rig.chain->set_enabled(1, false);
  Image input = pfx::test::test_image(16, 9);
  Image output = rig.render(input);
  CHECK(rig.chain->report().passes.empty());
  CHECK(rig.chain->report().peak_target_bytes == 0);
  CHECK(rig.chain->report().effects_skipped == std::vector<std::string>{"gain", "boxblur"});
  // A copy of the uploaded half values: within the one half conversion of the upload.
  for (size_t i = 0; i < input.rgba.size(); ++i) REQUIRE(output.rgba[i] == Approx(input.rgba[i]).epsilon(1.0 / 1024));

  // Changing a parameter turns the no-op into a pass on the next frame.
  rig.set("gain.gain=2");
  rig.render(input);
  CHECK(rig.chain->report().effects_run == std::vector<std::string>{"gain"});
  CHECK(rig.chain->report().passes.size() == 1);
}

TEST_CASE("plans_passes says whether render would run a pass, and runs nothing itself", "[chain]") {
  Rig rig;
  std::string error;
  const pfx_frame frame = pfx::test::make_frame(16, 9);
  bool passes = true;
  REQUIRE(rig.chain->plans_passes(frame, &passes, &error));
  CHECK(!passes);  // no effect at all
  REQUIRE(rig.chain->add("gain", &error));     // gain 1: a no-op
  REQUIRE(rig.chain->add("boxblur", &error));  // disabled below
  rig.set("boxblur.radius=3");
  rig.chain->set_enabled(1, false);
  passes = true;
  REQUIRE(rig.chain->plans_passes(frame, &passes, &error));
  CHECK(!passes);
  rig.chain->set_enabled(1, true);
  REQUIRE(rig.chain->plans_passes(frame, &passes, &error));
  CHECK(passes);
  rig.chain->set_enabled(1, false);
  rig.set("gain.gain=2");
  passes = false;
  REQUIRE(rig.chain->plans_passes(frame, &passes, &error));
  CHECK(passes);
  CHECK(rig.chain->report().frame == 0);  // no frame was rendered
}

TEST_CASE("a two-effect chain pools its targets below their sum", "[chain][pool]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("boxblur", &error));
  REQUIRE(rig.chain->add("boxblur", &error));
  rig.set("boxblur.radius=2");
  Image input = pfx::test::test_image(64, 32);
  rig.render(input);
  const auto& report = rig.chain->report();
  CHECK(report.passes.size() == 6);
  // Each boxblur has two 32x16 RGBA16F targets (4096 bytes each); the first one's output is a
  // 64x32 intermediate (16384 bytes). The second blur reuses the first one's two targets.
  CHECK(report.unpooled_target_bytes == 4 * 4096 + 16384);
  CHECK(report.peak_target_bytes == 2 * 4096 + 16384);
}

TEST_CASE("a blurred constant stays constant, and a resize is a re-plan, not a reload", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("boxblur", &error));
  rig.set("boxblur.radius=2");
  for (auto [w, h] : {std::pair{64, 32}, std::pair{33, 17}, std::pair{1, 1}, std::pair{64, 32}}) {
    Image input;
    input.width = w;
    input.height = h;
    input.rgba.assign(input.pixel_count() * 4, 0.75f);
    Image output = rig.render(input);
    INFO(w << "x" << h);
    for (float v : output.rgba) REQUIRE(v == Approx(0.75f).margin(1e-3));
    CHECK(rig.chain->plan().slots.size() == 2);
    CHECK(rig.chain->plan().slots[0].width == static_cast<uint32_t>(std::max(1L, std::lround(w * 0.5))));
  }
}

TEST_CASE("the chain reports pass times and names every pass", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("boxblur", &error));
  rig.set("boxblur.radius=1");
  rig.chain->set_timing(pfx::host::Timing::FINISH_AND_CLOCK);
  rig.render(pfx::test::test_image(32, 32));
  const auto& report = rig.chain->report();
  REQUIRE(report.passes.size() == 3);
  CHECK(report.passes[0].pass == "down");
  CHECK(report.passes[2].pass == "up");
  CHECK(report.timing == "finish+clock");
  double sum = 0;
  for (const auto& pass : report.passes) {
    CHECK(pass.ms > 0);
    sum += pass.ms;
  }
  CHECK(report.times.frame == report.frame);  // finish+clock: the frame's own times, at once
  CHECK(report.times.total_ms == Approx(sum));
}

TEST_CASE("chain errors name the effect", "[chain][errors]") {
  Rig rig;
  std::string error;
  CHECK_FALSE(rig.chain->add("bloom", &error));
  CHECK(error == "unknown effect 'bloom' (loaded: gain, boxblur)");
  REQUIRE(rig.chain->add("gain", &error));
  rig.set("gain.gain=2");
  pfx::host::FrameTextures none;
  CHECK_FALSE(rig.chain->render(pfx::test::make_frame(4, 4), none, 7, &error));
  CHECK(error == "the frame has no colour input");
}

TEST_CASE("reordering and removing effects changes what runs", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("gain", &error));
  REQUIRE(rig.chain->add("boxblur", &error));
  rig.set("gain.gain=2");
  rig.set("boxblur.radius=1");
  rig.chain->move(1, 0);
  rig.render(pfx::test::test_image(8, 8));
  CHECK(rig.chain->report().effects_run == std::vector<std::string>{"boxblur", "gain"});
  rig.chain->remove(0);
  rig.render(pfx::test::test_image(8, 8));
  CHECK(rig.chain->report().effects_run == std::vector<std::string>{"gain"});
}

// A host may give the chain a fresh output texture every frame and delete the last one. The chain
// keeps a framebuffer around each output texture it has drawn into; it must let go of those whose
// texture is gone, or it grows by a GL framebuffer (and the driver's memory behind it) per frame:
// Mesa does not hand a deleted texture's name out again.
TEST_CASE("a fresh output texture every frame leaves no framebuffer behind", "[chain]") {
  Rig rig;
  std::string error;
  REQUIRE(rig.chain->add("gain", &error));
  rig.set("gain.gain=2");  // not a no-op: the chain draws into the output
  const Image input = pfx::test::test_image(8, 4);
  // Every framebuffer name handed out so far, counted by asking for one more.
  auto framebuffers_alive = [] {
    GLuint probe = 0;
    glCreateFramebuffers(1, &probe);
    glDeleteFramebuffers(1, &probe);
    int alive = 0;
    for (GLuint name = 1; name < probe; ++name) alive += glIsFramebuffer(name) ? 1 : 0;
    return alive;
  };
  for (int frame = 0; frame < 5; ++frame) rig.render(input);
  const int after_5 = framebuffers_alive();
  for (int frame = 0; frame < 50; ++frame) rig.render(input);
  CHECK(framebuffers_alive() == after_5);
}
