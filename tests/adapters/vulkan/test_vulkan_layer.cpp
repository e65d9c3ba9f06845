// The Vulkan layer inside vkcube (package vulkan-tools), which no one here wrote, on lavapipe under
// Xvfb. vkcube turns its cube by a fixed step per frame, so its frame N is the same picture in
// every run: frame 5 through the layer with no effect (the bridge's copy in and out, bit for bit
// the application's frame: tests "vulkan.bridge") is the pristine frame, and pfx-render on it is
// what frame 5 through bloom must be.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "inject_run.hpp"
#include "layer_test_support.hpp"
#include "view_process.hpp"
#include "x11_windows.hpp"

namespace {

using pfx::test::ScratchFolder;

struct Frame {
  pfx::test::RunResult run;
  std::string log;
  pfx::app::DisplayImage presented, app;
};

// vkcube for 8 frames at 320x240 with the layer on and pfx-inject's variables `settings`
// (NAME=VALUE), frame 5 captured.
Frame vkcube_frame(const ScratchFolder& folder, const std::string& name, const std::vector<std::string>& settings,
                   bool validation = false) {
  std::vector<std::string> argv = {"/usr/bin/env",
                                   "XDG_DATA_HOME=" PFX_BUILD_SHARE,
                                   "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_LOG=" + folder.file(name + ".log"),
                                   "PFX_INJECT_CAPTURE=5:" + folder.file(name)};
  argv.insert(argv.end(), settings.begin(), settings.end());
  if (validation) argv.push_back("VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation");
  pfx::test::add_sanitizer_runtime(&argv);
  for (const char* arg : {PFX_VKCUBE, "--c", "8", "--width", "320", "--height", "240"}) argv.push_back(arg);
  Frame frame;
  frame.run = pfx::test::run_program(argv, 120);
  frame.log = pfx::test::read_text_file(folder.file(name + ".log"));
  // A run whose frames passed through captured nothing.
  if (std::filesystem::exists(folder.file(name + ".png"))) {
    frame.presented = pfx::test::read_png_file(folder.file(name + ".png"));
    frame.app = pfx::test::read_png_file(folder.file(name + ".app.png"));
  }
  return frame;
}

// The largest difference of any channel, and how many pixels differ at all.
std::pair<int, size_t> difference(const pfx::app::DisplayImage& a, const pfx::app::DisplayImage& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.channels == b.channels);
  int worst = 0;
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += size_t(a.channels)) {
    int here = 0;
    for (size_t c = 0; c < size_t(a.channels); ++c) here = std::max(here, std::abs(a.pixels[i + c] - b.pixels[i + c]));
    worst = std::max(worst, here);
    differing += here > 0;
  }
  return {worst, differing};
}

}  // namespace

TEST_CASE("vkcube's frame 5 through bloom is pfx-render's bloom of the pristine frame 5, within one code", "[vkcube]") {
  ScratchFolder folder("vulkan-vkcube");
  const Frame pristine = vkcube_frame(folder, "none", {"PFX_INJECT_CHAIN=none"});
  INFO(pristine.run.output << pristine.log);
  REQUIRE(pristine.run.exit_code == 0);
  REQUIRE(pristine.presented.width == 320);
  CHECK(difference(pristine.presented, pristine.app).first == 0);  // no effect: the frame untouched

  const Frame bloom = vkcube_frame(folder, "bloom", {"PFX_INJECT_CHAIN=bloom"});
  INFO(bloom.run.output << bloom.log);
  REQUIRE(bloom.run.exit_code == 0);
  CHECK(bloom.log.find("shared with the GL") != std::string::npos);
  // The application drew the same frame 5 in both runs.
  CHECK(difference(bloom.app, pristine.app).first == 0);
  const pfx::test::RunResult render =
      pfx::test::run_program({PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", folder.file("none.png"),
                              "--chain", "bloom", "--out", folder.file("render.png")});
  INFO(render.output);
  REQUIRE(render.exit_code == 0);
  const auto [worst, differing] = difference(bloom.presented, pfx::test::read_png_file(folder.file("render.png")));
  CHECK(worst <= 1);
  // Bloom at its display-referred defaults shows on vkcube's frame: round the bright logo and
  // edges (measured: 1,403 pixels, by up to 20 codes).
  const auto [changed_by, changed] = difference(bloom.presented, pristine.presented);
  CHECK(changed_by >= 8);
  CHECK(changed >= 320 * 240 / 100);
}

// pfx-inject --chain CHAIN -- vkcube at 320x240 for 8 frames, frame 5 captured as FOLDER/launched.png
// and the log in FOLDER/launched.log; `environment` (NAME=VALUE) set for both.
pfx::test::RunResult launch_vkcube(const ScratchFolder& folder, const std::string& chain,
                                   const std::vector<std::string>& environment) {
  std::vector<std::string> argv = {"/usr/bin/env"};
  argv.insert(argv.end(), environment.begin(), environment.end());
  pfx::test::add_sanitizer_runtime(&argv);
  for (const std::string& arg : {std::string(PFX_INJECT), std::string("--chain"), chain, std::string("--capture"),
                                 "5:" + folder.file("launched"), std::string("--quit-after"), std::string("8"),
                                 std::string("--log"), folder.file("launched.log"), std::string("--"),
                                 std::string(PFX_VKCUBE), std::string("--width"), std::string("320"),
                                 std::string("--height"), std::string("240")})
    argv.push_back(arg);
  return pfx::test::run_program(argv, 120);
}

// Whether the run's dynamic linker loaded Mesa's OpenGL driver (swrast_dri.so, kms_swrast_dri.so,
// ...), which making any GL context on this machine does: LD_DEBUG=files names every library a
// process loads.
bool loaded_a_gl_driver(const std::string& output) { return output.find("_dri.so") != std::string::npos; }

namespace {

// vkcube's frame 5 with no effect, through `settings` natively and through `settings` on the GL
// path (PFX_VK_NATIVE=0); `pristine_extra` goes to the first run too. Each run ended normally.
struct BothPaths {
  Frame pristine, native, gl;
};

BothPaths on_both_paths(const ScratchFolder& folder, const std::vector<std::string>& settings,
                        const std::vector<std::string>& pristine_extra = {}) {
  std::vector<std::string> none = {"PFX_INJECT_CHAIN=none"};
  none.insert(none.end(), pristine_extra.begin(), pristine_extra.end());
  std::vector<std::string> through_gl = settings;
  through_gl.push_back("PFX_VK_NATIVE=0");
  BothPaths frames{vkcube_frame(folder, "none", none), vkcube_frame(folder, "native", settings),
                   vkcube_frame(folder, "gl", through_gl)};
  INFO(frames.native.log << frames.gl.log);
  REQUIRE(frames.pristine.run.exit_code == 0);
  REQUIRE(frames.native.run.exit_code == 0);
  REQUIRE(frames.gl.run.exit_code == 0);
  REQUIRE(frames.native.presented.width == 320);
  REQUIRE(frames.gl.presented.width == 320);
  return frames;
}

// pfx-render's picture of the pristine frame (none.png in `folder`) through the layer test effect
// `fx_file` and the options after it.
pfx::app::DisplayImage rendered_from_pristine(const ScratchFolder& folder, const std::string& fx_file,
                                               const std::vector<std::string>& options) {
  std::vector<std::string> argv = {"/usr/bin/env", "PFX_FX_PATH=" PFX_LAYER_EFFECTS "/" + fx_file, PFX_RENDER,
                                   "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", folder.file("none.png"),
                                   "--out", folder.file("render.png")};
  argv.insert(argv.end(), options.begin(), options.end());
  const pfx::test::RunResult render = pfx::test::run_program(argv);
  INFO(render.output);
  REQUIRE(render.exit_code == 0);
  return pfx::test::read_png_file(folder.file("render.png"));
}

}  // namespace

TEST_CASE("an all-FX chain in vkcube runs natively with no GL in the process, and its frame 5 is pfx-render's of the "
          "pristine frame 5 and the GL path's, within one code",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-native");
  const std::vector<std::string> relief = {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx", "PFX_INJECT_CHAIN=fx_relief",
                                           "PFX_INJECT_SET=fx_relief.strength=2", "LD_DEBUG=files"};
  const auto [pristine, native, gl] = on_both_paths(folder, relief, {"LD_DEBUG=files"});
  INFO(native.log << gl.log);
  CHECK(native.log.find("the chain runs natively on the Vulkan device") != std::string::npos);
  CHECK(pristine.log.find("the chain runs natively on the Vulkan device") != std::string::npos);
  CHECK(gl.log.find("the chain runs through OpenGL: the GL path was asked for") != std::string::npos);
  // No GL context was made: the GL driver never loaded, where the GL path loads it.
  CHECK_FALSE(loaded_a_gl_driver(native.run.output));
  CHECK_FALSE(loaded_a_gl_driver(pristine.run.output));
  CHECK(loaded_a_gl_driver(gl.run.output));
  // Nor did the CPU wait for the device (the captures' read-backs aside), where the GL path waits
  // twice a frame.
  CHECK(native.log.find("; the CPU waited for the device 0 times") != std::string::npos);
  CHECK(gl.log.find("; the CPU waited for the device 0 times") == std::string::npos);
  CHECK(gl.log.find("; the CPU waited for the device") != std::string::npos);
  CHECK(difference(native.app, pristine.app).first == 0);
  CHECK(difference(pristine.presented, pristine.app).first == 0);
  const pfx::app::DisplayImage rendered =
      rendered_from_pristine(folder, "Relief.fx", {"--chain", "fx_relief", "--set", "fx_relief.strength=2"});
  CHECK(difference(native.presented, rendered).first <= 1);
  CHECK(difference(native.presented, gl.presented).first <= 1);
  // The relief shows on vkcube's frame: half of every pixel is the relief's grey.
  const auto [changed_by, changed] = difference(native.presented, pristine.presented);
  CHECK(changed_by >= 32);
  CHECK(changed >= 320 * 240 / 2);
}

TEST_CASE("pfx-inject --chain fx_relief -- vkcube: no GL driver in vkcube's process, and the frame the variables "
          "set by hand give",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-native-launcher");
  const Frame by_hand = vkcube_frame(folder, "by-hand", {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx",
                                                         "PFX_INJECT_CHAIN=fx_relief"});
  // The dynamic linker of every process pfx-inject starts writes the libraries it loads to
  // FOLDER/ld.PID.
  const pfx::test::RunResult launched =
      launch_vkcube(folder, "fx_relief",
                    {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx", "LD_DEBUG=files", "LD_DEBUG_OUTPUT=" + folder.file("ld")});
  const std::string log = pfx::test::read_text_file(folder.file("launched.log"));
  INFO(launched.output << log << by_hand.log);
  REQUIRE(launched.exit_code == 0);
  REQUIRE(by_hand.run.exit_code == 0);
  CHECK(log.find("the chain runs natively") != std::string::npos);
  // vkcube's process is the one that loaded pfx's layer.
  int with_layer = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path())) {
    if (entry.path().filename().string().rfind("ld.", 0) != 0) continue;
    const std::string loaded = pfx::test::read_text_file(entry.path().string());
    if (loaded.find("libpfxvulkanlayer") == std::string::npos) continue;
    ++with_layer;
    CHECK_FALSE(loaded_a_gl_driver(loaded));
  }
  CHECK(with_layer == 1);
  CHECK(difference(pfx::test::read_png_file(folder.file("launched.png")), by_hand.presented).first == 0);
}

TEST_CASE("through host memory vkcube's frame 5 is the shared-memory frame, bit for bit", "[vkcube]") {
  ScratchFolder folder("vulkan-host-memory");
  const Frame shared = vkcube_frame(folder, "shared", {"PFX_INJECT_CHAIN=bloom"});
  const Frame host = vkcube_frame(folder, "host", {"PFX_INJECT_CHAIN=bloom", "PFX_VK_HOST_MEMORY=1"});
  INFO(shared.run.output << shared.log << host.run.output << host.log);
  REQUIRE(shared.run.exit_code == 0);
  REQUIRE(host.run.exit_code == 0);
  CHECK(host.log.find("host memory asked for") != std::string::npos);
  CHECK(difference(host.presented, shared.presented).first == 0);
}

TEST_CASE("the Khronos validation layer below the layer reports no error, on either path", "[vkcube]") {
  ScratchFolder folder("vulkan-validation");
  for (const char* host_memory : {"PFX_VK_HOST_MEMORY=0", "PFX_VK_HOST_MEMORY=1"}) {
    const Frame frame = vkcube_frame(folder, "validated", {"PFX_INJECT_CHAIN=bloom", host_memory}, true);
    INFO(host_memory << "\n" << frame.run.output << frame.log);
    REQUIRE(frame.run.exit_code == 0);
    CHECK(frame.run.output.find("Validation") == std::string::npos);
    CHECK(frame.presented.width == 320);  // the layer did run
  }
}

TEST_CASE("the Khronos validation layer above the layer reports no error", "[vkcube]") {
  // What the application sees of pfx's layer (its swapchains, its presents) is checked from above.
  // Layers enabled by VK_INSTANCE_LAYERS always go below the implicit ones, so the validation
  // layer comes in as an implicit layer of its own, through a copy of its manifest found before
  // pfx's (the loader puts the implicit manifest it finds first nearest the application).
  ScratchFolder folder("vulkan-validation-above");
  std::filesystem::create_directories(folder.file("vulkan/implicit_layer.d"));
  std::ifstream official(PFX_VALIDATION_MANIFEST);
  std::string manifest((std::istreambuf_iterator<char>(official)), std::istreambuf_iterator<char>());
  const size_t type = manifest.find("\"type\"");
  REQUIRE(type != std::string::npos);
  manifest.insert(type, "\"enable_environment\": {\"PFX_TEST_VALIDATION\": \"1\"}, "
                        "\"disable_environment\": {\"PFX_TEST_NO_VALIDATION\": \"1\"}, ");
  std::ofstream(folder.file("vulkan/implicit_layer.d/validation.json")) << manifest;
  const Frame frame = vkcube_frame(folder, "validated",
                                   {"XDG_DATA_HOME=" + folder.path(), "XDG_DATA_DIRS=" PFX_BUILD_SHARE ":/usr/share",
                                    "PFX_TEST_VALIDATION=1", "VK_LOADER_DEBUG=layer", "PFX_INJECT_CHAIN=bloom"});
  INFO(frame.run.output << frame.log);
  REQUIRE(frame.run.exit_code == 0);
  // The loader's account of the device's layers, application side first.
  const size_t stack = frame.run.output.find("vkCreateDevice layer callstack setup");
  REQUIRE(stack != std::string::npos);
  const size_t validation = frame.run.output.find("VK_LAYER_KHRONOS_validation", stack);
  const size_t pfx = frame.run.output.find("VK_LAYER_PFX_post_effects", stack);
  REQUIRE(validation != std::string::npos);
  REQUIRE(pfx != std::string::npos);
  CHECK(validation < pfx);
  CHECK(frame.run.output.find("Validation") == std::string::npos);
  CHECK(frame.presented.width == 320);  // the layer did run
}

TEST_CASE("a setting that does not apply is left out, said in one line, and the rest of the chain runs", "[vkcube]") {
  ScratchFolder folder("vulkan-bad-setting");
  const Frame bloom = vkcube_frame(folder, "bloom", {"PFX_INJECT_CHAIN=bloom"});
  INFO(bloom.run.output << bloom.log);
  REQUIRE(bloom.presented.width == 320);
  int run = 0;
  for (const std::vector<std::string>& settings :
       {std::vector<std::string>{"PFX_INJECT_CHAIN=nosuch,bloom"},
        std::vector<std::string>{"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_SET=bloom.threshold=abc"}}) {
    const Frame frame = vkcube_frame(folder, "bad" + std::to_string(++run), settings);
    INFO(settings.back() << "\n" << frame.run.output << frame.log);
    CHECK(frame.run.exit_code == 0);
    size_t ignored = 0;
    for (size_t at = frame.log.find("ignored "); at != std::string::npos; at = frame.log.find("ignored ", at + 1)) ++ignored;
    CHECK(ignored == 1);
    CHECK(frame.log.find(run == 1 ? "nosuch" : "threshold") != std::string::npos);
    CHECK(frame.log.find("frames pass through") == std::string::npos);
    // bloom at its defaults ran: the frame of the chain without the bad item.
    REQUIRE(frame.presented.width == 320);
    CHECK(difference(frame.presented, bloom.presented).first == 0);
  }
}

// Replaces the file the way editors and pfx-view write one: a new file renamed over the old.
void replace_file(const ScratchFolder& folder, const std::string& path, const std::string& text) {
  std::ofstream(folder.file("replacing.tmp")) << text;
  std::filesystem::rename(folder.file("replacing.tmp"), path);
}

namespace {

// The command line of vkcube at 160x120 with the layer on and `settings` (NAME=VALUE), its frame
// `last_frame` captured as FOLDER/last.png (and last.app.png), quitting after it: a run long
// enough for edits made while it runs to apply well before that frame.
std::vector<std::string> vkcube_until(const ScratchFolder& folder, const std::vector<std::string>& settings,
                                      int last_frame) {
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_CAPTURE=" + std::to_string(last_frame) + ":" + folder.file("last"),
                                   "PFX_INJECT_QUIT_AFTER=" + std::to_string(last_frame + 1)};
  argv.insert(argv.end(), settings.begin(), settings.end());
  pfx::test::add_sanitizer_runtime(&argv);
  for (const char* arg : {PFX_VKCUBE, "--c", "100000", "--width", "160", "--height", "120"}) argv.push_back(arg);
  return argv;
}

}  // namespace

TEST_CASE("an edited preset applies while vkcube runs, and one that does not read leaves the chain running",
          "[vkcube]") {
  ScratchFolder folder("vulkan-preset-edit");
  const std::string preset = folder.file("look.json");
  std::ofstream(preset) << R"({"pfx_preset": 1, "chain": [{"effect": "bloom"}]})";
  // Frame 2,000 is captured: long after the edits below, which apply within a quarter of a second.
  pfx::test::ViewerProcess app(vkcube_until(folder, {"PFX_INJECT_PRESET=" + preset}, 2000));
  REQUIRE_FALSE(app.wait_for_line("the chain runs", 60).empty());
  // Other effects: made anew.
  replace_file(folder, preset, R"({"pfx_preset": 1, "chain": [{"effect": "glare"}, {"effect": "bloom", "enabled": false}]})");
  CHECK_FALSE(app.wait_for_line("settings applied: chain glare,bloom (off)", 10).empty());
  replace_file(folder, preset, R"({"pfx_preset": 1, "chain": [{"effect": "glare"}, )");  // saved half-way
  CHECK_FALSE(app.wait_for_line("the previous chain keeps running", 10).empty());
  // The same effects with other values and flags: the values reach the running effects.
  const std::string last = R"({"pfx_preset": 1, "chain": [{"effect": "glare", "enabled": false}, {"effect": "bloom"}],
                               "parameters": {"bloom": {"strength": 2.5}}})";
  replace_file(folder, preset, last);
  CHECK_FALSE(app.wait_for_line("settings applied: chain glare (off),bloom", 10).empty());
  const std::string quit = app.wait_for_line("quitting, as asked", 120);
  INFO(app.output());
  REQUIRE_FALSE(quit.empty());
  CHECK(app.wait_exit(30) == 0);
  std::ofstream(folder.file("last-preset.json")) << last;
  const pfx::test::RunResult render =
      pfx::test::run_program({PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", folder.file("last.app.png"),
                              "--preset", folder.file("last-preset.json"), "--out", folder.file("render.png")});
  INFO(render.output);
  REQUIRE(render.exit_code == 0);
  const auto presented = pfx::test::read_png_file(folder.file("last.png"));
  CHECK(difference(presented, pfx::test::read_png_file(folder.file("render.png"))).first <= 1);
  // Bloom at strength 2.5 is far from bloom at its default there.
  CHECK(difference(presented, pfx::test::read_png_file(folder.file("last.app.png"))).first >= 8);
}

TEST_CASE("frames before --from-frame pass through untouched and the chain runs from that frame on", "[vkcube]") {
  ScratchFolder folder("vulkan-from-frame");
  const Frame bloom = vkcube_frame(folder, "bloom", {"PFX_INJECT_CHAIN=bloom"});
  REQUIRE(bloom.presented.width == 320);
  const Frame late = vkcube_frame(folder, "late", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_FROM_FRAME=6"});
  INFO(late.run.output << late.log);
  CHECK(late.run.exit_code == 0);
  CHECK(late.log.find("frame 5: capture") != std::string::npos);
  CHECK(late.log.find("not written: frames before --from-frame pass through") != std::string::npos);
  CHECK(late.presented.width == 0);  // frame 5 went by untouched, so nothing captured it
  const Frame from5 = vkcube_frame(folder, "from5", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_FROM_FRAME=5"});
  INFO(from5.run.output << from5.log);
  REQUIRE(from5.presented.width == 320);
  CHECK(difference(from5.presented, bloom.presented).first == 0);
}

TEST_CASE("pfx-inject -- vkcube runs the chain through the layer, as the variables set by hand do", "[vkcube]") {
  ScratchFolder folder("vulkan-launcher");
  const Frame by_hand = vkcube_frame(folder, "by-hand", {"PFX_INJECT_CHAIN=bloom"});
  const pfx::test::RunResult launched = launch_vkcube(folder, "bloom", {});
  INFO(launched.output << pfx::test::read_text_file(folder.file("launched.log")) << by_hand.log);
  REQUIRE(launched.exit_code == 0);
  REQUIRE(by_hand.run.exit_code == 0);
  CHECK(difference(pfx::test::read_png_file(folder.file("launched.png")), by_hand.presented).first == 0);
}

TEST_CASE("two windows presented together each go through the chain, and a device destroyed at once after its "
          "last presents ends cleanly", "[two_windows]") {
  // No application here has two windows: two_windows.c presents both swapchains in one call, and
  // destroys its swapchains and device without waiting for the presents.
  ScratchFolder folder("vulkan-two-windows");
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_CHAIN=bloom", "PFX_INJECT_LOG=" + folder.file("two.log"),
                                   "PFX_INJECT_CAPTURE=5:" + folder.file("two")};
  pfx::test::add_sanitizer_runtime(&argv);
  argv.insert(argv.end(), {PFX_TWO_WINDOWS, "8"});
  const pfx::test::RunResult run = pfx::test::run_program(argv, 120);
  INFO(run.output << pfx::test::read_text_file(folder.file("two.log")));
  REQUIRE(run.exit_code == 0);
  CHECK(run.output.find("8 frames presented to two windows") != std::string::npos);
  // The first window's capture is PREFIX, the second's PREFIX-2, each at its window's size.
  const std::pair<std::string, int> windows[] = {{"two", 160}, {"two-2", 201}};
  for (const auto& [name, width] : windows) {
    INFO(name);
    const auto presented = pfx::test::read_png_file(folder.file(name + ".png"));
    const auto app = pfx::test::read_png_file(folder.file(name + ".app.png"));
    REQUIRE(presented.width == width);
    const pfx::test::RunResult render =
        pfx::test::run_program({PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", folder.file(name + ".app.png"),
                                "--chain", "bloom", "--out", folder.file(name + "-render.png")});
    REQUIRE(render.exit_code == 0);
    CHECK(difference(presented, pfx::test::read_png_file(folder.file(name + "-render.png"))).first <= 1);
    CHECK(difference(presented, app).first >= 8);  // the bright square glows
  }
}

TEST_CASE("a window hidden from the screen and shown again, as a minimised one is, keeps both windows going "
          "through the chain", "[two_windows]") {
  // two_windows unmaps its second window at frame 10 of 30 and maps it again at frame 20 (without
  // a window manager, what iconifying does), presenting both all along, as X11 applications do.
  ScratchFolder folder("vulkan-minimised");
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_CHAIN=bloom", "PFX_INJECT_LOG=" + folder.file("hidden.log"),
                                   "PFX_INJECT_CAPTURE=15:" + folder.file("hidden") + "\n25:" + folder.file("shown")};
  pfx::test::add_sanitizer_runtime(&argv);
  argv.insert(argv.end(), {PFX_TWO_WINDOWS, "30", "minimise"});
  const pfx::test::RunResult run = pfx::test::run_program(argv, 120);
  const std::string log = pfx::test::read_text_file(folder.file("hidden.log"));
  INFO(run.output << log);
  REQUIRE(run.exit_code == 0);
  CHECK(run.output.find("frame 10: second window hidden") != std::string::npos);
  CHECK(run.output.find("frame 20: second window shown again") != std::string::npos);
  CHECK(run.output.find("30 frames presented to two windows") != std::string::npos);
  CHECK(log.find("pass through") == std::string::npos);
  // While hidden and after: each window's frame is pfx-render's bloom of what the application drew.
  for (const char* name : {"hidden", "hidden-2", "shown", "shown-2"}) {
    INFO(name);
    const auto presented = pfx::test::read_png_file(folder.file(std::string(name) + ".png"));
    const pfx::test::RunResult render = pfx::test::run_program(
        {PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", folder.file(std::string(name) + ".app.png"),
         "--chain", "bloom", "--out", folder.file(std::string(name) + "-render.png")});
    REQUIRE(render.exit_code == 0);
    CHECK(difference(presented, pfx::test::read_png_file(folder.file(std::string(name) + "-render.png"))).first <= 1);
    CHECK(difference(presented, pfx::test::read_png_file(folder.file(std::string(name) + ".app.png"))).first >= 8);
  }
}

TEST_CASE("a dry run (--dry-run) runs the chain on every present and presents vkcube's own frames", "[vkcube]") {
  ScratchFolder folder("vulkan-dry-run");
  const Frame pristine = vkcube_frame(folder, "none", {"PFX_INJECT_CHAIN=none"});
  REQUIRE(pristine.presented.width == 320);
  // The frame times pfx-inject --bench reads count the presents whose frame went through a pass.
  const std::string stats = folder.file("dry.json");
  const Frame dry = vkcube_frame(folder, "dry", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_DRY_RUN=1",
                                                 "PFX_INJECT_STATS=" + stats, "PFX_INJECT_QUIT_AFTER=8"});
  const std::string text = pfx::test::read_text_file(stats);
  INFO(dry.run.output << dry.log << text);
  REQUIRE(dry.run.exit_code == 0);
  REQUIRE(dry.presented.width == 320);
  CHECK(difference(dry.presented, pristine.presented).first == 0);
  CHECK(difference(dry.app, pristine.app).first == 0);
  CHECK(text.find("\"frames\": 8,") != std::string::npos);
  CHECK(text.find("\"frames_through_chain\": 8,") != std::string::npos);
  CHECK(text.find("\"chain\": \"bloom\"") != std::string::npos);
  // Without --dry-run the same chain changes what is presented.
  const Frame bloom = vkcube_frame(folder, "bloom", {"PFX_INJECT_CHAIN=bloom"});
  REQUIRE(bloom.presented.width == 320);
  CHECK(difference(bloom.presented, pristine.presented).first > 1);
}

TEST_CASE("the pass times the panel shows come from a Vulkan application's chain too", "[vkcube]") {
  ScratchFolder folder("vulkan-timings");
  const std::string timings = folder.file("timings.json");
  const Frame frame = vkcube_frame(folder, "timed", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_TIMINGS=" + timings});
  const std::string text = pfx::test::read_text_file(timings);
  INFO(frame.run.output << frame.log << text);
  REQUIRE(frame.run.exit_code == 0);
  CHECK(text.find("\"chain\":\"bloom\"") != std::string::npos);
  // On this machine's software renderer passes are timed with glFinish and a clock.
  CHECK(text.find("\"timing\":\"finish+clock\"") != std::string::npos);
  // Bloom's passes, from its bright pass to its composite, each with a time.
  CHECK(text.find("{\"effect\":\"bloom\",\"pass\":\"bright\",\"ms\":") != std::string::npos);
  CHECK(text.find("{\"effect\":\"bloom\",\"pass\":\"composite\",\"ms\":") != std::string::npos);
  CHECK(text.find("\"total_ms\":0,") == std::string::npos);
}

TEST_CASE("pfx-inject --bench -- vkcube reports the application alone, an empty chain and the chain", "[vkcube]") {
  ScratchFolder folder("vulkan-bench");
  std::vector<std::string> argv = {"/usr/bin/env"};
  pfx::test::add_sanitizer_runtime(&argv);
  for (const std::string& arg :
       {std::string(PFX_INJECT), std::string("--chain"), std::string("bloom"), std::string("--bench"), std::string("20"),
        std::string("--bench-runs"), std::string("1"), std::string("--bench-json"), folder.file("bench.json"),
        std::string("--"), std::string(PFX_VKCUBE), std::string("--width"), std::string("320"), std::string("--height"),
        std::string("240")})
    argv.push_back(arg);
  const pfx::test::RunResult run = pfx::test::run_program(argv, 180);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  for (const char* row : {"| application alone | - |", "| empty chain | none |", "| chain | bloom |"})
    CHECK(run.output.find(row) != std::string::npos);
  // The unit was timed on the layer's GL context, at vkcube's size.
  const std::string json = pfx::test::read_text_file(folder.file("bench.json"));
  INFO(json);
  const size_t unit = json.find("\"copy_pass_ms\": ");
  REQUIRE(unit != std::string::npos);
  CHECK(std::stod(json.substr(unit + std::strlen("\"copy_pass_ms\": "))) > 0);
}


// mpv playing FFmpeg's test source through its Vulkan output with pfx's layer running `chain`
// (with `settings`, NAME=VALUE), its 10th present captured: it ends normally, the chain shows, and
// the frame is pfx-render's of mpv's own frame within one code. Returns pfx's log.
std::string check_mpv(const std::string& name, const std::string& chain, const std::vector<std::string>& settings) {
  ScratchFolder folder("vulkan-mpv-" + name);
  const std::string device = pfx::test::lavapipe_device_name();
  REQUIRE(!device.empty());
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_CHAIN=" + chain, "PFX_INJECT_LOG=" + folder.file("mpv.log"),
                                   "PFX_INJECT_CAPTURE=10:" + folder.file("mpv")};
  argv.insert(argv.end(), settings.begin(), settings.end());
  pfx::test::add_sanitizer_runtime(&argv);
  // A clip made by FFmpeg's test source inside mpv (colour bars, a moving gradient, a clock), every
  // frame shown and none dropped however loaded the machine is, so that the 10th present exists.
  for (const std::string& arg : {std::string(PFX_MPV), std::string("--no-config"), std::string("--really-quiet"),
                                 std::string("--vo=gpu"), std::string("--gpu-api=vulkan"), "--vulkan-device=" + device,
                                 std::string("--no-audio"), std::string("--untimed"), std::string("--framedrop=no"),
                                 std::string("--frames=15"),
                                 std::string("av://lavfi:testsrc2=size=320x240:rate=25:duration=1")})
    argv.push_back(arg);
  const pfx::test::RunResult run = pfx::test::run_program(argv, 120);
  const std::string log = pfx::test::read_text_file(folder.file("mpv.log"));
  INFO(run.output << log);
  REQUIRE(run.exit_code == 0);
  const pfx::app::DisplayImage presented = pfx::test::read_png_file(folder.file("mpv.png"));
  const pfx::app::DisplayImage app = pfx::test::read_png_file(folder.file("mpv.app.png"));
  const auto [changed_by, changed] = difference(presented, app);
  CHECK(changed_by >= 16);
  CHECK(changed >= 320 * 240 / 20);
  std::vector<std::string> render_argv = {"/usr/bin/env"};
  render_argv.insert(render_argv.end(), settings.begin(), settings.end());
  for (const std::string& arg : {std::string(PFX_RENDER), std::string("--plugins"), std::string(PFX_PLUGIN_OUTPUT_DIR),
                                 std::string("--input"), folder.file("mpv.app.png"), std::string("--chain"), chain,
                                 std::string("--out"), folder.file("render.png")})
    render_argv.push_back(arg);
  const pfx::test::RunResult render = pfx::test::run_program(render_argv);
  REQUIRE(render.exit_code == 0);
  CHECK(difference(presented, pfx::test::read_png_file(folder.file("render.png"))).first <= 1);
  return log;
}

TEST_CASE("mpv playing through its Vulkan output shows bloom, the frame pfx-render gives, and ends normally", "[mpv]") {
  check_mpv("bloom", "bloom", {});
}

TEST_CASE("mpv playing through its Vulkan output with an FX effect natively shows it, the frame pfx-render gives, and "
          "ends normally",
          "[mpv][native]") {
  const std::string log = check_mpv("native", "fx_relief", {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx"});
  CHECK(log.find("the chain runs natively") != std::string::npos);
}

namespace {

// "frame 4500: resident memory 98765 KiB; heap in use 1234567 bytes" -> 1234567, or -1.
long long heap_at(const std::string& log, uint64_t frame) {
  const std::string key = "frame " + std::to_string(frame) + ": resident memory ";
  const size_t at = log.find(key);
  if (at == std::string::npos) return -1;
  const size_t heap = log.find("heap in use ", at);
  return heap == std::string::npos ? -1 : std::atoll(log.c_str() + heap + 12);
}

}  // namespace

// The heap in use after frames 4,500, 6,500 and 8,500 of vkcube (64x64) with pfx-inject's
// variables `settings`, and its log. The heap holds what lavapipe and llvmpipe allocate for every
// Vulkan and GL object too (their images and textures are malloc'd), so a leaked image, texture
// or command buffer shows there.
struct HeapUse {
  long long first = 0, middle = 0, last = 0;
  std::string log;
};
HeapUse heap_over_8500_presents(const std::string& name, const std::vector<std::string>& settings) {
  ScratchFolder folder("vulkan-8500-" + name);
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_LOG=" + folder.file("long.log"),
                                   "PFX_INJECT_RESOURCES_AT=4500,6500,8500"};
  argv.insert(argv.end(), settings.begin(), settings.end());
  pfx::test::add_sanitizer_runtime(&argv);
  for (const char* arg : {PFX_VKCUBE, "--c", "8500", "--width", "64", "--height", "64"}) argv.push_back(arg);
  const pfx::test::RunResult run = pfx::test::run_program(argv, 300);
  HeapUse use;
  use.log = pfx::test::read_text_file(folder.file("long.log"));
  INFO(run.output << use.log);
  REQUIRE(run.exit_code == 0);
  use.first = heap_at(use.log, 4500);
  use.middle = heap_at(use.log, 6500);
  use.last = heap_at(use.log, 8500);
  REQUIRE(use.first > 0);
  REQUIRE(use.middle > 0);
  REQUIRE(use.last > 0);
  return use;
}

TEST_CASE("8,500 presents of vkcube through the default chain do not grow the heap", "[vkcube][long]") {
  // The bound is half of what a 16-byte block lost per frame adds over 2,000 frames.
  //
  // Measured from frame 4,500: lavapipe's vkCmdBlitImage makes one allocation of about 1 MB
  // after its first ~8,200 blits, whatever the frame's size (two blits a frame step at frame
  // ~4,100, one a frame at ~8,200), and none after that through 13,000 frames.
  const HeapUse use = heap_over_8500_presents("default", {});
  INFO(use.log);
  CHECK(use.log.find("left out of the default chain") != std::string::npos);
  CHECK(use.middle - use.first <= 16000);
  CHECK(use.last - use.middle <= 16000);
}

TEST_CASE("8,500 presents of vkcube through an FX effect on the native path do not grow the heap",
          "[vkcube][long][native]") {
  // The same bound, over the native path's command buffers, fences, and the effect's images,
  // pipelines and descriptor sets.
  const HeapUse use = heap_over_8500_presents(
      "native", {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx", "PFX_INJECT_CHAIN=fx_relief"});
  INFO(use.log);
  CHECK(use.log.find("the chain runs natively") != std::string::npos);
  CHECK(use.middle - use.first <= 16000);
  CHECK(use.last - use.middle <= 16000);
}

TEST_CASE("vkBasalt's CAS and pfx's bloom in one stack, in either order", "[vkcube][vkbasalt]") {
  ScratchFolder folder("vulkan-vkbasalt");
  std::ofstream(folder.file("vkBasalt.conf")) << "effects = cas\n";
  const std::string basalt = "VKBASALT_CONFIG_FILE=" + folder.file("vkBasalt.conf");
  const Frame pristine = vkcube_frame(folder, "none", {"PFX_INJECT_CHAIN=none"});
  REQUIRE(pristine.run.exit_code == 0);
  auto render_bloom = [&](const std::string& input, const std::string& output) {
    const pfx::test::RunResult render = pfx::test::run_program(
        {PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", input, "--chain", "bloom", "--out", output});
    REQUIRE(render.exit_code == 0);
    return pfx::test::read_png_file(output);
  };

  SECTION("pfx above vkBasalt (both implicit; the loader puts the manifest found first nearest the application)") {
    const Frame both = vkcube_frame(folder, "above", {"PFX_INJECT_CHAIN=bloom", "ENABLE_VKBASALT=1", basalt});
    INFO(both.run.output << both.log);
    REQUIRE(both.run.exit_code == 0);
    // pfx sees the application's frame and gives bloom's; vkBasalt then works on what pfx presents.
    CHECK(difference(both.app, pristine.app).first == 0);
    CHECK(difference(both.presented, render_bloom(folder.file("none.png"), folder.file("above-render.png"))).first <= 1);
  }
  SECTION("pfx below vkBasalt (pfx's layer enabled as an explicit one)") {
    pfx::test::write_explicit_manifest(folder);
    const Frame both = vkcube_frame(folder, "below",
                                    {"XDG_DATA_HOME=" + folder.path(), "VK_LAYER_PATH=" + folder.path(),
                                     "VK_INSTANCE_LAYERS=VK_LAYER_PFX_post_effects", "PFX_INJECT_CHAIN=bloom",
                                     "ENABLE_VKBASALT=1", basalt});
    INFO(both.run.output << both.log);
    REQUIRE(both.run.exit_code == 0);
    // vkBasalt's sharpening reached pfx, and pfx's bloom went over it.
    const auto [sharpened_by, sharpened] = difference(both.app, pristine.app);
    CHECK(sharpened_by >= 8);
    CHECK(sharpened >= 320 * 240 / 100);
    CHECK(difference(both.presented, render_bloom(folder.file("below.app.png"), folder.file("below-render.png"))).first <=
          1);
    CHECK(difference(both.presented, both.app).first >= 8);
  }
}


TEST_CASE("vkcube resized mid-run: the re-created swapchain's frames go through the chain at their new size",
          "[vkcube][resize]") {
  ScratchFolder folder("vulkan-resize");
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_INJECT_CHAIN=bloom", "PFX_INJECT_QUIT_AFTER=400",
                                   "PFX_INJECT_CAPTURE=400:" + folder.file("frame400")};
  pfx::test::add_sanitizer_runtime(&argv);
  for (const char* arg : {PFX_VKCUBE, "--width", "320", "--height", "240"}) argv.push_back(arg);
  pfx::test::ViewerProcess vkcube(argv);
  REQUIRE(!vkcube.wait_for_line("the chain runs", 60).empty());
  REQUIRE(pfx::test::keep_trying([] { return pfx::test::resize_window(320, 240, 200, 150); }));
  REQUIRE(vkcube.wait_exit(120) == 0);
  INFO(vkcube.output());
  // The last frame is of the new size, and bloom ran over it as pfx-render runs it.
  const std::string last = folder.file("frame400");
  const pfx::app::DisplayImage presented = pfx::test::read_png_file(last + ".png");
  CHECK(presented.width == 200);
  CHECK(presented.height == 150);
  const pfx::test::RunResult render = pfx::test::run_program(
      {PFX_RENDER, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--input", last + ".app.png", "--chain", "bloom", "--out",
       folder.file("render.png")});
  REQUIRE(render.exit_code == 0);
  CHECK(difference(presented, pfx::test::read_png_file(folder.file("render.png"))).first <= 1);
  CHECK(vkcube.output().find("pass through") == std::string::npos);
}

TEST_CASE("an effect of a chosen chain that needs depth is switched off, said once, and the rest runs", "[vkcube]") {
  ScratchFolder folder("vulkan-depth");
  const Frame with_dof = vkcube_frame(folder, "dof-bloom", {"PFX_INJECT_CHAIN=dof,bloom"});
  const Frame bloom = vkcube_frame(folder, "bloom", {"PFX_INJECT_CHAIN=bloom"});
  INFO(with_dof.run.output << with_dof.log);
  REQUIRE(with_dof.run.exit_code == 0);
  CHECK(with_dof.log.find("dof off: needs depth") != std::string::npos);
  CHECK(difference(with_dof.presented, bloom.presented).first == 0);
}

TEST_CASE("an FX effect that reads depth where a frame has one runs in vkcube on both paths, reading the far plane, "
          "as pfx-render runs it on the frame vkcube drew",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-haze");
  const std::vector<std::string> haze = {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Haze.fx", "PFX_INJECT_CHAIN=fx_haze"};
  const auto [pristine, native, gl] = on_both_paths(folder, haze);
  INFO(native.log << gl.log);
  CHECK(native.log.find("the chain runs natively on the Vulkan device") != std::string::npos);
  CHECK(gl.log.find("fx_haze off") == std::string::npos);
  const pfx::app::DisplayImage rendered = rendered_from_pristine(folder, "Haze.fx", {"--chain", "fx_haze"});
  CHECK(difference(native.presented, rendered).first <= 1);
  CHECK(difference(gl.presented, rendered).first <= 1);
  // The far plane everywhere: every pixel 0.6 of the way to the haze's colour.
  const auto [changed_by, changed] = difference(native.presented, pristine.presented);
  CHECK(changed_by >= 32);
  CHECK(changed >= 320 * 240 * 9 / 10);
}

namespace {

// A ReShade preset running Tinted.fx with the preprocessor definitions `definitions`.
std::string tint_preset(const std::string& definitions) {
  return "PreprocessorDefinitions=" + definitions + "\nTechniques=Tinted@Tinted.fx\nTechniqueSorting=Tinted@Tinted.fx\n";
}

// The largest distance of `presented` from `app` tinted by `amount` towards Tinted.fx's orange, in
// 8-bit codes (FX effects read and write the display's codes as they are).
int distance_from_tinted(const pfx::app::DisplayImage& presented, const pfx::app::DisplayImage& app, double amount) {
  REQUIRE(presented.pixels.size() == app.pixels.size());
  const double orange[3] = {255.0, 127.5, 0.0};
  int worst = 0;
  for (size_t i = 0; i < app.pixels.size(); i += size_t(app.channels))
    for (size_t c = 0; c < 3; ++c) {
      const double expected = app.pixels[i + c] + (orange[c] - app.pixels[i + c]) * amount;
      worst = std::max(worst, int(std::lround(std::abs(presented.pixels[i + c] - expected))));
    }
  return worst;
}

// The run of vkcube_until ended normally, natively all along, and its last frame is the
// application's tinted by `amount`.
void ends_natively_tinted(pfx::test::ViewerProcess& app, const ScratchFolder& folder, double amount) {
  const std::string quit = app.wait_for_line("quitting, as asked", 120);
  INFO(app.output());
  REQUIRE_FALSE(quit.empty());
  CHECK(app.wait_exit(30) == 0);
  CHECK(app.output().find("through OpenGL") == std::string::npos);
  const auto presented = pfx::test::read_png_file(folder.file("last.png"));
  CHECK(distance_from_tinted(presented, pfx::test::read_png_file(folder.file("last.app.png")), amount) <= 1);
}

}  // namespace

TEST_CASE("an FX effect the Vulkan runtime cannot run (a pass drawing into a 3D texture) sends the chain through "
          "OpenGL, said in the log, and runs there as pfx-render runs it",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-volume");
  const Frame volume =
      vkcube_frame(folder, "volume", {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Volume.fx", "PFX_INJECT_CHAIN=fx_volume"});
  INFO(volume.run.output << volume.log);
  REQUIRE(volume.run.exit_code == 0);
  CHECK(volume.log.find("the chain runs through OpenGL: fx_volume runs on OpenGL only") != std::string::npos);
  CHECK(volume.log.find("pass through") == std::string::npos);
  REQUIRE(volume.presented.width == 320);
  std::filesystem::copy_file(folder.file("volume.app.png"), folder.file("none.png"));
  const pfx::app::DisplayImage rendered = rendered_from_pristine(folder, "Volume.fx", {"--chain", "fx_volume"});
  CHECK(difference(volume.presented, rendered).first <= 1);
  // Half way to orange everywhere (the 3D texture's first layer, drawn by the first pass).
  CHECK(distance_from_tinted(volume.presented, volume.app, 0.5) <= 1);
}

TEST_CASE("a preset's preprocessor definitions run natively in vkcube, giving the GL path's and pfx-render's frame",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-definitions");
  std::ofstream(folder.file("tint.ini")) << tint_preset("TINT_AMOUNT=0.5");
  const std::vector<std::string> tinted = {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Tinted.fx",
                                           "PFX_INJECT_PRESET=" + folder.file("tint.ini")};
  const auto [pristine, native, gl] = on_both_paths(folder, tinted);
  INFO(native.log << gl.log);
  CHECK(native.log.find("the chain runs natively on the Vulkan device") != std::string::npos);
  const pfx::app::DisplayImage rendered =
      rendered_from_pristine(folder, "Tinted.fx", {"--preset", folder.file("tint.ini")});
  CHECK(difference(native.presented, rendered).first <= 1);
  CHECK(difference(gl.presented, rendered).first <= 1);
  // Half way to orange, as the definition asks (the file's default, 0, would change nothing).
  CHECK(distance_from_tinted(native.presented, pristine.presented, 0.5) <= 1);
  CHECK(distance_from_tinted(gl.presented, pristine.presented, 0.5) <= 1);
}

TEST_CASE("new preprocessor definitions in an edited preset apply natively while vkcube runs, and a malformed list "
          "or one the file does not compile with leaves the chain running",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-definitions-edit");
  const std::string preset = folder.file("tint.ini");
  std::ofstream(preset) << tint_preset("TINT_AMOUNT=0.5");
  // Frame 1,500 is captured: long after the edits below, which apply within a quarter of a second.
  pfx::test::ViewerProcess app(
      vkcube_until(folder, {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Tinted.fx", "PFX_INJECT_PRESET=" + preset}, 1500));
  REQUIRE_FALSE(app.wait_for_line("the chain runs natively", 60).empty());
  replace_file(folder, preset, tint_preset("1TINT=0.5"));
  const std::string refused = app.wait_for_line("the previous chain keeps running", 10);
  CHECK(refused.find("'1TINT' is not a macro name") != std::string::npos);
  // Definitions the file does not compile with: the instances made with them fail, the running
  // ones stay (as the GL path keeps the last version that compiled).
  replace_file(folder, preset, tint_preset("TINT_AMOUNT=*"));
  // The compiler's errors take lines of their own before the line that ends the message.
  CHECK_FALSE(app.wait_for_line("the previous chain keeps running", 60).empty());
  CHECK(app.output().find("fx_tinted' could not be made on Vulkan") != std::string::npos);
  replace_file(folder, preset, tint_preset("TINT_AMOUNT=0.25"));
  CHECK_FALSE(app.wait_for_line("settings applied: chain fx_tinted", 10).empty());
  ends_natively_tinted(app, folder, 0.25);
}

TEST_CASE("an FX file edited while vkcube runs natively reloads there, and an edit that does not compile leaves the "
          "last version running",
          "[vkcube][native]") {
  ScratchFolder folder("vulkan-fx-reload");
  // Tinted.fx with its amount written into the file, as a user edits a number.
  std::ifstream original(PFX_LAYER_EFFECTS "/Tinted.fx");
  const std::string text((std::istreambuf_iterator<char>(original)), std::istreambuf_iterator<char>());
  const auto version = [&](const std::string& amount) { return "#define TINT_AMOUNT " + amount + "\n" + text; };
  const std::string file = folder.file("Tinted.fx");
  std::ofstream(file) << version("0.5");
  pfx::test::ViewerProcess app(
      vkcube_until(folder, {"PFX_FX_PATH=" + file, "PFX_INJECT_CHAIN=fx_tinted", "PFX_INJECT_RESOURCES_AT=2"}, 5000));
  REQUIRE_FALSE(app.wait_for_line("the chain runs natively", 60).empty());
  // The first frames ran with the first version, before any edit.
  REQUIRE_FALSE(app.wait_for_line("frame 2: resident memory", 60).empty());
  replace_file(folder, file, version("*"));
  CHECK_FALSE(app.wait_for_line("The last version that compiled keeps running", 30).empty());
  // Frame 5,000 is captured: long after the edit below, which applies within a quarter of a
  // second (the reload itself is logged at the plugin's info level, which the layer leaves out).
  replace_file(folder, file, version("0.25"));
  ends_natively_tinted(app, folder, 0.25);
}

TEST_CASE("captures asked for when the chain has failed are each named in the log with the reason, once",
          "[vkcube]") {
  // The test grade's LUT texture is not there: the effect fails at its first frame, and from then
  // on frames pass through.
  ScratchFolder folder("vulkan-capture-after-failure");
  std::vector<std::string> argv = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE, "ENABLE_PFX_VULKAN=1",
                                   "PFX_FX_PATH=" PFX_FX_TESTS "/files/Grade.fx", "PFX_INJECT_CHAIN=fx_grade",
                                   "PFX_INJECT_LOG=" + folder.file("failed.log"),
                                   "PFX_INJECT_CAPTURE=1:" + folder.file("first") + "\n5:" + folder.file("fifth") +
                                       "\nall:" + folder.file("every-%d")};
  pfx::test::add_sanitizer_runtime(&argv);
  for (const char* arg : {PFX_VKCUBE, "--c", "8", "--width", "160", "--height", "120"}) argv.push_back(arg);
  const pfx::test::RunResult run = pfx::test::run_program(argv, 120);
  const std::string log = pfx::test::read_text_file(folder.file("failed.log"));
  INFO(run.output << log);
  REQUIRE(run.exit_code == 0);
  REQUIRE(log.find("frame 1: frames pass through from now on: effect 'fx_grade'") != std::string::npos);
  const std::string why = " not written: the chain failed and frames pass through";
  CHECK(log.find("frame 1: capture " + folder.file("first") + why) != std::string::npos);
  CHECK(log.find("frame 5: capture " + folder.file("fifth") + why) != std::string::npos);
  const std::string every = "captures all:" + folder.file("every-%d") + " are not written while the chain failed";
  const size_t said = log.find(every);
  CHECK(said != std::string::npos);
  CHECK(log.find(every, said + 1) == std::string::npos);
  for (const char* name : {"first.png", "fifth.png", "every-1.png", "every-8.png"})
    CHECK_FALSE(std::filesystem::exists(folder.file(name)));
}
