// The state-leak oracle. With glmark2's clock stopped every frame of a scene is the same picture,
// so a frame the application draws after the chain ran must equal one it drew before any pfx code
// ever ran in its process: a difference means pfx left GL state behind that changed the
// application's drawing. The chain runs in full on every frame (--dry-run only presents the
// application's own frame, so the presented frames must match too).
//
// The reference is frame 2 of a run whose chain starts at frame 2 (--from-frame 2): frame 2
// rather than frame 1 because glmark2's pulsar, buffer and jellyfish draw their first frame
// differently even with the clock stopped (measured with the chain never running at all); for
// the other scenes frames 1 and 2 are the same picture.
#include <catch2/catch.hpp>

#include "inject_run.hpp"

using namespace pfx::test;

namespace {

constexpr int kFrames = 5;
// Everything blooms, so the chain changes every scene's frame, dark ones included.
constexpr const char* kThreshold = "bloom.threshold=0.02";

// Under a stopped clock these two draw a black frame (pulsar from its second frame on): for
// them the comparison can only catch a leak that makes them draw something.
bool draws_black_when_stopped(const std::string& scene) { return scene == "pulsar" || scene == "ideas"; }

bool has_content(const pfx::app::DisplayImage& image) {
  for (auto value : image.pixels)
    if (value != 0) return true;
  return false;
}

void check_no_state_leaks(const std::string& scene) {
  ScratchFolder folder("oracle-" + scene);
  const InjectRun reference = run_injected(
      folder, "reference", {"--dry-run", "--chain", "bloom,dof", "--set", kThreshold, "--from-frame", "2", "--quit-after", "2", "--capture",
                            "2:" + folder.file("reference")},
      glmark2_scene(scene));
  INFO(reference.result.output << reference.log);
  REQUIRE(reference.result.exit_code == 0);
  const InjectRun run = run_injected(folder, "chain",
                                     {"--dry-run", "--chain", "bloom,dof", "--set", kThreshold, "--quit-after",
                                      std::to_string(kFrames),
                                      "--capture", "all:" + folder.file("frame%d")},
                                     glmark2_scene(scene));
  INFO(run.result.output << run.log);
  REQUIRE(run.result.exit_code == 0);
  // glmark2 looks its present call up with dlsym on the libGL it opened.
  REQUIRE(run.log.find("hooked glXSwapBuffers (looked up with dlsym)") != std::string::npos);
  REQUIRE(run.log.find("pass through") == std::string::npos);

  const auto drawn_before = read_exr_file(folder.file("reference.app.exr"));
  const auto presented_before = read_png_file(folder.file("reference.png"));
  CHECK(has_content(presented_before) != draws_black_when_stopped(scene));
  for (int frame = 2; frame <= kFrames; ++frame) {
    const std::string prefix = folder.file("frame" + std::to_string(frame));
    INFO("frame " << frame);
    CHECK(same_pixels(read_exr_file(prefix + ".app.exr"), drawn_before));
    CHECK(same_pixels(read_png_file(prefix + ".png"), presented_before));
  }
  // The chain really ran: its output is not the frame it was given.
  if (!draws_black_when_stopped(scene))
    CHECK_FALSE(same_pixels(read_exr_file(folder.file("frame3.out.exr")), read_exr_file(folder.file("frame3.app.exr"))));
}

}  // namespace

#define PFX_ORACLE_CASE(scene)                                                                              \
  TEST_CASE("glmark2 -b " scene ": frames drawn after the chain ran equal one drawn before it ever ran",  \
            "[oracle]") {                                                                                    \
    check_no_state_leaks(scene);                                                                             \
  }

PFX_ORACLE_CASE("build")
PFX_ORACLE_CASE("texture")
PFX_ORACLE_CASE("shading")
PFX_ORACLE_CASE("bump")
PFX_ORACLE_CASE("effect2d")
PFX_ORACLE_CASE("pulsar")
PFX_ORACLE_CASE("desktop")
PFX_ORACLE_CASE("buffer")
PFX_ORACLE_CASE("ideas")
PFX_ORACLE_CASE("jellyfish")
PFX_ORACLE_CASE("terrain")
PFX_ORACLE_CASE("shadow")
PFX_ORACLE_CASE("refract")
PFX_ORACLE_CASE("conditionals")
PFX_ORACLE_CASE("function")
PFX_ORACLE_CASE("loop")
