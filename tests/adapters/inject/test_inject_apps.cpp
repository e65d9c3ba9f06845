// pfx-inject in real applications no one here wrote: glxgears (links libGL and calls
// glXSwapBuffers directly, compatibility profile), glmark2 (opens libGL itself and finds
// glXSwapBuffers with dlsym) and glmark2-es2 (OpenGL ES through EGL, which pfx refuses).
#include <catch2/catch.hpp>

#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "inject_run.hpp"
#include "png_io.hpp"
#include "tonemap.hpp"

using namespace pfx::test;

namespace {

std::vector<std::string> glxgears() { return {PFX_GLXGEARS}; }

void write_text(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
}

// The presented frame with every effect of the chain off (nothing copied in or out) and
// the one presented in a dry run must be the same bits.
void check_round_trip(const std::vector<std::string>& app, const std::string& transfer) {
  ScratchFolder folder("round-trip");
  const std::string preset = folder.file("off.json");
  write_text(preset, R"({"pfx_preset": 1, "chain": [{"effect": "bloom", "enabled": false}]})");
  const InjectRun dry = run_injected(folder, "dry", {"--dry-run", "--chain", "bloom", "--transfer", transfer,
                                                     "--quit-after", "3", "--capture", "3:" + folder.file("dry")},
                                     app);
  INFO(dry.result.output << dry.log);
  REQUIRE(dry.result.exit_code == 0);
  const InjectRun off = run_injected(folder, "off", {"--preset", preset, "--transfer", transfer, "--quit-after", "3",
                                                     "--capture", "3:" + folder.file("off")},
                                     app);
  INFO(off.result.output << off.log);
  REQUIRE(off.result.exit_code == 0);
  REQUIRE(off.log.find("chain: bloom (off)") != std::string::npos);
  const auto presented = read_png_file(folder.file("off.png"));
  CHECK(same_pixels(presented, read_png_file(folder.file("dry.png"))));
  // Not a blank window: the application drew something the round trip had to keep.
  bool varied = false;
  for (size_t i = 3; i < presented.pixels.size() && !varied; ++i) varied = presented.pixels[i] != presented.pixels[i % 3];
  CHECK(varied);
}

}  // namespace

TEST_CASE("glxgears: with every effect off the presented frame is the application's, bit for bit (sRGB)") {
  check_round_trip(glxgears(), "srgb");
}

TEST_CASE("glmark2: with every effect off the presented frame is the application's, bit for bit (sRGB and linear)") {
  check_round_trip(glmark2_scene("shading"), "srgb");
  check_round_trip(glmark2_scene("shading"), "linear");
}

TEST_CASE("a captured frame run through pfx-render gives the injector's presented frame, and the chain visibly changed it") {
  ScratchFolder folder("capture");
  // Every value the two hosts could start differently is set.
  const std::vector<std::string> look = {"--chain", "bloom", "--set", "bloom.threshold=0.4", "--set", "bloom.knee=0",
                                         "--set", "bloom.strength=2"};
  std::vector<std::string> args = look;
  args.insert(args.end(), {"--quit-after", "3", "--capture", "3:" + folder.file("shot")});
  const InjectRun run = run_injected(folder, "chain", args, glmark2_scene("shading"));
  INFO(run.result.output << run.log);
  REQUIRE(run.result.exit_code == 0);
  // The frame as the chain received it, back in 8-bit codes (the capture holds them decoded with
  // the exact curve, which half float keeps to within 0.05 of a code): what pfx-render takes as an
  // 8-bit frame, through the same 8-bit path as pfx-inject's.
  const pfx::app::Image received = read_exr_file(folder.file("shot.app.exr"));
  pfx::app::DisplayImage codes;
  codes.width = received.width;
  codes.height = received.height;
  codes.channels = 3;
  for (size_t i = 0; i < received.rgba.size(); ++i)
    if (i % 4 != 3) codes.pixels.push_back(pfx::app::encode_srgb8(received.rgba[i]));
  std::string error;
  REQUIRE(pfx::app::write_png(folder.file("received.png"), codes, &error));
  std::vector<std::string> render = {PFX_RENDER, "--input", folder.file("received.png"), "--out", folder.file("render.png")};
  render.insert(render.end(), look.begin(), look.end());
  const RunResult rendered = run_program(render);
  INFO(rendered.output);
  REQUIRE(rendered.exit_code == 0);
  CHECK(same_pixels(read_png_file(folder.file("render.png")), read_png_file(folder.file("shot.png"))));

  const InjectRun dry = run_injected(folder, "dry", {"--dry-run", "--chain", "bloom", "--quit-after", "3", "--capture",
                                                     "3:" + folder.file("app")},
                                     glmark2_scene("shading"));
  REQUIRE(dry.result.exit_code == 0);
  const PngDifference difference = compare_png(folder.file("shot.png"), folder.file("app.png"));
  CHECK(difference.max >= 32);
  CHECK(difference.mean >= 1.0);
}

TEST_CASE("glmark2-es2's OpenGL ES context passes through with one log line, says its capture is not written, and the application runs on") {
  ScratchFolder folder("es2");
  const InjectRun run = run_injected(folder, "es2", {"--chain", "bloom", "--quit-after", "5", "--capture", "3:" + folder.file("shot")},
                                     {PFX_GLMARK2_ES2, "-s", "96x64", "-b", "shading"}, false);
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.log.find("hooked eglSwapBuffers") != std::string::npos);
  CHECK(run.log.find("an OpenGL ES context: pfx needs desktop OpenGL 4.5; its frames pass through untouched") !=
        std::string::npos);
  // A capture asked for there is said not to be written, with the reason.
  CHECK(run.log.find("frame 3: capture " + folder.file("shot") +
                     " not written: its context's frames pass through (an OpenGL ES context") != std::string::npos);
  CHECK(run.log.find("quitting after 5 presented frames") != std::string::npos);
}

TEST_CASE("a context below OpenGL 4.5 passes through with one log line") {
  ScratchFolder folder("gl33");
  const InjectRun run = run_injected(folder, "gl33", {"--chain", "bloom", "--quit-after", "5"}, glxgears(), false,
                                     {"MESA_GL_VERSION_OVERRIDE=3.3"});
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.log.find("hooked glXSwapBuffers (linked directly)") != std::string::npos);
  CHECK(run.log.find("OpenGL 3.3") != std::string::npos);
  CHECK(run.log.find("pfx needs OpenGL 4.5; its frames pass through untouched") != std::string::npos);
}

TEST_CASE("an effect that fails to create leaves the application running to its own end") {
  ScratchFolder folder("broken");
  const std::string plugins =
      plugin_folder_with(folder, std::string(PFX_TEST_RELOADABLE_DIR) + "/reloadable_broken_shader.so");
  // No --quit-after and a running clock: glmark2 ends the scene itself.
  const InjectRun run = run_injected(folder, "broken", {"--plugins", plugins, "--chain", "tint"},
                                     {PFX_GLMARK2, "-s", "96x64", "-b", "build:duration=0.5"}, false);
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.result.output.find("glmark2 Score") != std::string::npos);
  CHECK(run.log.find("effect 'tint' could not be created") != std::string::npos);
  CHECK(run.log.find("its frames pass through untouched") != std::string::npos);
}

TEST_CASE("glmark2's context per scene: each is hooked, the destroyed one's chain freed, and it runs to its end") {
  ScratchFolder folder("contexts");
  const InjectRun run = run_injected(folder, "contexts", {"--chain", "bloom"},
                                     {PFX_GLMARK2, "-s", "96x64", "-b", "build:duration=0.3", "-b", "shading:duration=0.3"},
                                     false);
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.result.output.find("glmark2 Score") != std::string::npos);
  CHECK(run.log.find("in GLX context 1; chain: bloom") != std::string::npos);
  CHECK(run.log.find("GLX context 1 destroyed: its chain freed") != std::string::npos);
  CHECK(run.log.find("in GLX context 2; chain: bloom") != std::string::npos);
}

TEST_CASE("an application that never presents is left alone") {
  ScratchFolder folder("offscreen");
  const InjectRun run = run_injected(folder, "offscreen", {"--chain", "bloom"},
                                     {PFX_GLMARK2, "--off-screen", "-s", "96x64", "-b", "build:duration=0.3"}, false);
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.result.output.find("glmark2 Score") != std::string::npos);
  CHECK(run.log.find("hooked") == std::string::npos);
}

TEST_CASE("an edited preset applies while the application runs") {
  ScratchFolder folder("reload");
  const std::string preset = folder.file("look.json");
  write_text(preset, R"({"pfx_preset": 1, "chain": [{"effect": "bloom"}]})");
  std::vector<std::string> argv = {"/usr/bin/env"};
#if defined(__SANITIZE_ADDRESS__)
  const char* asan_options = std::getenv("ASAN_OPTIONS");  // see run_injected
  argv.push_back(std::string("ASAN_OPTIONS=") + (asan_options ? asan_options : "") + ":verify_asan_link_order=0");
#endif
  argv.insert(argv.end(), {"FAKETIME=2020-01-01 00:00:00", std::string("LD_PRELOAD=") + PFX_FAKETIME_LIBRARY, PFX_INJECT,
                           "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--preset", preset, "--", PFX_GLMARK2, "-s", "96x64", "-b",
                           "build"});
  ViewerProcess app(argv);
  REQUIRE_FALSE(app.wait_for_line("chain: bloom", 60).empty());
  // A new modification time even on a file system with coarse stamps.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write_text(folder.file("look.tmp"),
             R"({"pfx_preset": 1, "chain": [{"effect": "glare"}, {"effect": "bloom", "enabled": false}]})");
  std::filesystem::rename(folder.file("look.tmp"), preset);
  INFO(app.output());
  CHECK_FALSE(app.wait_for_line("preset applied: chain glare,bloom (off)", 10).empty());
  // What of it is not there is left out with one warning, and the rest applies.
  write_text(folder.file("look.tmp"), R"({"pfx_preset": 1, "chain": [{"effect": "no-such-effect"}, {"effect": "bloom"}]})");
  std::filesystem::rename(folder.file("look.tmp"), preset);
  CHECK_FALSE(app.wait_for_line("look.json: left out: no-such-effect (not loaded)", 10).empty());
  CHECK_FALSE(app.wait_for_line("preset applied: chain bloom", 10).empty());
  // One that does not read (saved half-way) keeps the chain that runs.
  write_text(folder.file("look.tmp"), R"({"pfx_preset": 1, "chain": [{"effect": "glare"}, )");
  std::filesystem::rename(folder.file("look.tmp"), preset);
  CHECK_FALSE(app.wait_for_line("the previous chain keeps running", 10).empty());
}

TEST_CASE("an edited FX file shows within half a second while the application runs, a broken edit keeps the last good one") {
  ScratchFolder folder("fx-edit");
  std::filesystem::create_directories(folder.file("Shaders"));
  const std::string grade = folder.file("Shaders/Grade.fx");
  std::filesystem::copy_file(std::string(PFX_FX_TEST_SHADERS) + "/Grade.fx", grade);
  const std::string source = read_text_file(grade);
  // The effect looks at its files by the steady clock: no libfaketime here, and glmark2 runs until
  // it is stopped.
  std::vector<std::string> argv = {"/usr/bin/env", "PFX_FX_PATH=" + folder.file("Shaders")};
  const std::string runtime = sanitizer_runtime();
  if (!runtime.empty()) argv.push_back("LD_PRELOAD=" + runtime);
  argv.insert(argv.end(), {PFX_INJECT, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--chain", "fx_grade", "--",
                           PFX_GLMARK2, "-s", "96x64", "-b", "build:duration=60"});
  ViewerProcess app(argv);
  INFO(app.output());
  REQUIRE_FALSE(app.wait_for_line("chain: fx_grade", 60).empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // frames with the first version
  const std::string plain = "c = Mode == 0 ? c * Gain :";
  REQUIRE(source.find(plain) != std::string::npos);
  std::string edited = source;
  edited.replace(edited.find(plain), plain.size(), "c = Mode == 0 ? c * Gain * 0.25 :");
  auto save_whole = [&](const std::string& text) {
    write_text(grade + ".new", text);
    std::filesystem::rename(grade + ".new", grade);
  };
  const auto saved = std::chrono::steady_clock::now();
  save_whole(edited);
  REQUIRE_FALSE(app.wait_for_line("reloaded " + grade, 10).empty());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - saved).count();
  INFO("the edit showed " << seconds << " s after the file was saved");
#if defined(__SANITIZE_ADDRESS__)
  CHECK(seconds <= 2.0);  // every compile is slower under the sanitizers
#else
  CHECK(seconds <= 0.5);
#endif
  save_whole(edited + "\nfloat4 Broken( {\n");
  CHECK_FALSE(app.wait_for_line("The last version that compiled keeps running", 10).empty());
  app.send(SIGTERM);
  app.wait_exit(30);
}

TEST_CASE("pfx-inject --bench reports the application alone, with an empty chain and with the chain") {
  const RunResult run = run_program({PFX_INJECT, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--chain", "bloom", "--bench", "20",
                                     "--bench-runs", "1", "--", PFX_GLXGEARS});
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  for (const char* row : {"| application alone | - |", "| empty chain | none", "| chain | bloom |"})
    CHECK(run.output.find(row) != std::string::npos);
  // The unit was measured inside the application: a positive time, not a zero left by a failure.
  const size_t unit = run.output.find("copy pass (the unit): ");
  REQUIRE(unit != std::string::npos);
  CHECK(std::strtod(run.output.c_str() + unit + std::string("copy pass (the unit): ").size(), nullptr) > 0);
}

TEST_CASE("a pass that raises a GL error turns the chain off with one log line and the application runs to its end") {
  ScratchFolder folder("gl-error");
  const std::string plugins =
      plugin_folder_with(folder, std::string(PFX_TEST_MISBEHAVING_PLUGIN_DIR) + "/broken_raises_gl_error.so");
  const InjectRun run = run_injected(folder, "gl-error", {"--plugins", plugins, "--chain", "broken_raises_gl_error"},
                                     {PFX_GLMARK2, "-s", "96x64", "-b", "build:duration=0.5"}, false);
  INFO(run.result.output << run.log);
  CHECK(run.result.exit_code == 0);
  CHECK(run.result.output.find("glmark2 Score") != std::string::npos);
  CHECK(run.log.find("frame 1: effect 'broken_raises_gl_error' pass 'copy' raised GL error 0x0500; this context's "
                     "frames pass through untouched from now on") != std::string::npos);
  // Said once: the frames after it pass through without trying again.
  CHECK(run.log.find("raised GL error", run.log.find("raised GL error") + 1) == std::string::npos);
}
