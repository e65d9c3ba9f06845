// pfx's Vulkan layer under the Khronos validation layer (package vulkan-validationlayers), in
// applications nobody here wrote: vkcube (vulkan-tools), mpv through both its Vulkan outputs, and
// vkd3d-gears (vkd3d-demos: Direct3D 12 through vkd3d), in the states a user reaches: no effect,
// an effect, an effect that changes nothing, a ReShade FX effect, a preset switched off and on
// while the application runs, each path (native on the application's device, through the GL by
// either memory), vkBasalt stacked either way, a resized and a minimised window, the end at
// --quit-after.
//
// The validation layer goes below pfx's (VK_INSTANCE_LAYERS), where it sees what pfx submits as
// well as what the application does, checks synchronisation too, and logs every message of every
// kind (errors, warnings, performance warnings) to a file. The application alone, under the same validation and doing the
// same, is the reference: a kind of message it does not give itself is pfx's, and fails the test.
// (The applications are not all clean: mpv logs hundreds of errors of its own, as libplacebo names
// its objects through an extension it did not enable.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "inject_run.hpp"
#include "layer_test_support.hpp"
#include "view_process.hpp"
#include "x11_windows.hpp"

namespace {

using pfx::test::ScratchFolder;

// "VUID-vkQueueSubmit-fence-00064 (ERROR / SPEC)" -> how many times it was logged.
using Messages = std::map<std::string, int>;

// The messages of the validation layer's log: each starts a line with its id and its kind,
// "VUID-...(ERROR / SPEC): msgNum: ...". A message about an object the application named (the
// layer writes the name after the handle: "VkSemaphore 0x19[swapchain out]") is the
// application's, whatever else happens: pfx names none of its objects. (mpv destroys a semaphore
// it named "swapchain out" while its last present still waits on it, in one run of about 15,
// with pfx's layer or without.)
Messages read_messages(const std::string& path) {
  static const std::regex first_line(R"(^([A-Za-z0-9_.-]+)\(([A-Z]+ / [A-Z]+)\): msgNum:)");
  static const std::regex named_object(R"(0x[0-9a-fA-F]+\[[^\]]+\])");
  Messages messages;
  std::ifstream file(path);
  std::string line;
  std::smatch match;
  while (std::getline(file, line))
    if (std::regex_search(line, match, first_line) && !std::regex_search(line, named_object))
      ++messages[match[1].str() + " (" + match[2].str() + ")"];
  return messages;
}

// The kinds of message in `with` that `alone` (the application without pfx) never gave, with their
// counts, one a line; empty when there are none.
std::string messages_not_in(const Messages& with, const Messages& alone) {
  std::string text;
  for (const auto& [message, count] : with)
    if (!alone.count(message)) text += message + " x" + std::to_string(count) + "\n";
  return text;
}

TEST_CASE("validation messages are read by kind and counted, and those the application gives alone or about objects "
          "it named are set aside",
          "[validation]") {
  ScratchFolder folder("vulkan-validation-messages");
  // As the validation layer of Debian 12 writes them.
  std::ofstream(folder.file("log.txt"))
      << "UNASSIGNED-GeneralParameterError-ExtensionNotEnabled(ERROR / SPEC): msgNum: -383040211 - Validation "
         "Error: [ UNASSIGNED-GeneralParameterError-ExtensionNotEnabled ] Object 0: ...\n"
         "\n    Objects: 1\n        [0] 0x7fb0b41a7440, type: 1, name: NULL\n"
         "VUID-vkQueueSubmit-fence-00064(ERROR / SPEC): msgNum: 1 - Validation Error: [ VUID-vkQueueSubmit-fence-00064 ]\n"
         "UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout(WARN / PERF): msgNum: 2 - Validation Performance "
         "Warning: ...\n"
         "VUID-vkQueueSubmit-fence-00064(ERROR / SPEC): msgNum: 1 - Validation Error: again\n"
         "VUID-vkDestroySemaphore-semaphore-01137(ERROR / SPEC): msgNum: -1588160456 - Validation Error: [ "
         "VUID-vkDestroySemaphore-semaphore-01137 ] Object 0: handle = 0x7ff6083dd940, type = VK_OBJECT_TYPE_DEVICE; | "
         "MessageID = 0xa1569838 | Cannot call vkDestroySemaphore on VkSemaphore 0x190000000019[swapchain out] that is "
         "currently in use by a command buffer.\n";
  const Messages messages = read_messages(folder.file("log.txt"));
  CHECK(messages == Messages{{"UNASSIGNED-GeneralParameterError-ExtensionNotEnabled (ERROR / SPEC)", 1},
                             {"VUID-vkQueueSubmit-fence-00064 (ERROR / SPEC)", 2},
                             {"UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout (WARN / PERF)", 1}});
  const Messages alone = {{"UNASSIGNED-GeneralParameterError-ExtensionNotEnabled (ERROR / SPEC)", 385}};
  CHECK(messages_not_in(messages, alone) ==
        "UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout (WARN / PERF) x1\n"
        "VUID-vkQueueSubmit-fence-00064 (ERROR / SPEC) x2\n");
  CHECK(messages_not_in(alone, alone).empty());
}

struct App {
  std::string name;
  std::vector<std::string> counted;  // a run that ends by itself after a few frames; empty: none
  std::vector<std::string> endless;  // a run that goes on until its window is closed
  unsigned width = 320, height = 240;
};

App vkcube() {
  return {"vkcube",
          {PFX_VKCUBE, "--c", "8", "--width", "320", "--height", "240"},
          {PFX_VKCUBE, "--width", "320", "--height", "240"}};
}

App mpv(const std::string& output) {
  // A clip made by FFmpeg's test source inside mpv, every frame shown and none dropped.
  const std::vector<std::string> player = {PFX_MPV,
                                           "--no-config",
                                           "--really-quiet",
                                           "--vo=" + output,
                                           "--gpu-api=vulkan",
                                           "--vulkan-device=" + pfx::test::lavapipe_device_name(),
                                           "--no-audio",
                                           "--untimed",
                                           "--framedrop=no"};
  App app{"mpv-" + output, player, player};
  app.counted.insert(app.counted.end(), {"--frames=15", "av://lavfi:testsrc2=size=320x240:rate=25:duration=1"});
  // Ten minutes of video, more than any session lasts (mpv stops presenting when it loops a clip
  // of the test source).
  app.endless.push_back("av://lavfi:testsrc2=size=320x240:rate=25:duration=600");
  return app;
}

App vkd3d_gears() { return {"vkd3d-gears", {}, {PFX_VKD3D_GEARS}, 300, 300}; }

// The environment (an `env` command line) of a run named `name`: the validation layer's settings,
// its messages to FOLDER/NAME.validation.txt, and with pfx its layer, the variables `settings`
// (NAME=VALUE), and its log to FOLDER/NAME.log unless log_to_output.
std::vector<std::string> validated_environment(const ScratchFolder& folder, const std::string& name, bool with_pfx,
                                               const std::vector<std::string>& settings, bool log_to_output = false) {
  const std::string settings_folder = folder.file(name + "-settings");
  std::filesystem::create_directories(settings_folder);
  std::ofstream(settings_folder + "/vk_layer_settings.txt")
      << "khronos_validation.report_flags = error,warn,perf\n"
         "khronos_validation.enables = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT\n"
         "khronos_validation.debug_action = VK_DBG_LAYER_ACTION_LOG_MSG\n"
         "khronos_validation.log_filename = "
      << folder.file(name + ".validation.txt") << "\n";
  std::vector<std::string> env = {"/usr/bin/env", "XDG_DATA_HOME=" PFX_BUILD_SHARE,
                                  "VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation",
                                  "VK_LAYER_SETTINGS_PATH=" + settings_folder};
  if (with_pfx) env.push_back("ENABLE_PFX_VULKAN=1");
  if (with_pfx && !log_to_output) env.push_back("PFX_INJECT_LOG=" + folder.file(name + ".log"));
  env.insert(env.end(), settings.begin(), settings.end());
  pfx::test::add_sanitizer_runtime(&env);
  return env;
}

struct Validated {
  int exit_code = -1;
  std::string output;  // the application's, and pfx's log
  Messages messages;
};

// The counted run of the application under validation: with pfx's layer and `settings`, or alone.
// An application with no counted run is ended by pfx's --quit-after.
Validated run_counted(const ScratchFolder& folder, const std::string& name, const App& app, bool with_pfx,
                      std::vector<std::string> settings = {}) {
  if (app.counted.empty()) settings.push_back("PFX_INJECT_QUIT_AFTER=12");
  std::vector<std::string> argv = validated_environment(folder, name, with_pfx, settings);
  argv.insert(argv.end(), app.counted.empty() ? app.endless.begin() : app.counted.begin(),
              app.counted.empty() ? app.endless.end() : app.counted.end());
  const pfx::test::RunResult run = pfx::test::run_program(argv, 180);
  return {run.exit_code, run.output + pfx::test::read_text_file(folder.file(name + ".log")),
          read_messages(folder.file(name + ".validation.txt"))};
}

// A session: the endless run under validation (with pfx, its log read as it comes), `script`
// played once the application's window is up, then the window closed as a user closes it (at
// closed_size when the script resized it).
using Script = std::function<void(pfx::test::ViewerProcess& app, bool with_pfx)>;
struct Size {
  unsigned width = 0, height = 0;
};
Validated run_session(const ScratchFolder& folder, const std::string& name, const App& app, bool with_pfx,
                      const std::vector<std::string>& settings, const Script& script, Size closed_size = {}) {
  std::vector<std::string> argv = validated_environment(folder, name, with_pfx, settings, true);
  argv.insert(argv.end(), app.endless.begin(), app.endless.end());
  pfx::test::ViewerProcess process(argv);
  if (!pfx::test::keep_trying([&] { return pfx::test::window_exists(app.width, app.height); }, 30)) {
    const int exit_code = process.wait_exit(1);
    FAIL(name << ": no " << app.width << "x" << app.height << " window after 30 s (windows: "
              << pfx::test::describe_windows() << "; exit code " << exit_code << ")\n"
              << process.output());
  }
  script(process, with_pfx);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  if (!closed_size.width) closed_size = {app.width, app.height};
  CHECK(pfx::test::keep_trying([&] { return pfx::test::close_window(closed_size.width, closed_size.height); }, 10));
  Validated result;
  result.exit_code = process.wait_exit(60);
  result.output = process.output();
  result.messages = read_messages(folder.file(name + ".validation.txt"));
  return result;
}

// Waits for pfx's layer to say it runs (at the first present); fails with what the application said.
void wait_for_the_layer(pfx::test::ViewerProcess& process) {
  if (process.wait_for_line("the chain runs", 60).empty())
    FAIL("pfx's layer did not start within 60 s (windows: " << pfx::test::describe_windows() << ")\n"
                                                            << process.output());
}

// What every run with pfx must show: the application ended normally, pfx's layer ran and never
// gave up, and the validation layer said nothing that the application alone does not say.
void check_clean(const Validated& run, const Validated& alone) {
  INFO(run.output);
  CHECK(run.exit_code == 0);
  CHECK(run.output.find("the chain runs") != std::string::npos);
  CHECK(run.output.find("pass through") == std::string::npos);
  CHECK(messages_not_in(run.messages, alone.messages) == "");
}

// The paths a chain's frames can take: natively on the application's device where every effect
// runs on Vulkan, else (and when asked) through the GL by shared or host memory.
std::vector<std::pair<std::string, std::vector<std::string>>> paths_for(bool runs_natively) {
  std::vector<std::pair<std::string, std::vector<std::string>>> paths;
  if (runs_natively) paths.push_back({"native", {}});
  for (const char* host_memory : {"0", "1"}) {
    std::vector<std::string> settings = {std::string("PFX_VK_HOST_MEMORY=") + host_memory};
    if (runs_natively) settings.push_back("PFX_VK_NATIVE=0");
    paths.push_back({std::string("host-memory-") + host_memory, settings});
  }
  return paths;
}

// The chains a user reaches, on every path each can take.
void check_every_chain(const App& app) {
  ScratchFolder folder("vulkan-validation-" + app.name);
  const Validated alone = app.counted.empty()
                              ? run_session(folder, "alone", app, false, {}, [](auto&, bool) {
                                  std::this_thread::sleep_for(std::chrono::seconds(1));
                                })
                              : run_counted(folder, "alone", app, false);
  INFO(app.name << " alone:\n" << alone.output);
  REQUIRE(alone.exit_code == 0);
  struct Chain {
    std::string name;
    std::vector<std::string> settings;
    bool runs_natively;
  };
  const std::vector<Chain> chains = {
      {"none", {"PFX_INJECT_CHAIN=none"}, true},
      {"bloom", {"PFX_INJECT_CHAIN=bloom"}, false},
      {"bloom-strength-0", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_SET=bloom.strength=0"}, false},
      // Five passes, four render targets drawn at once, targets cleared.
      {"fx", {"PFX_FX_PATH=" PFX_FX_TESTS "/conformance/render_targets.fx", "PFX_INJECT_CHAIN=fx_render_targets"}, true}};
  for (const auto& chain : chains) {
    for (const auto& [path, path_settings] : paths_for(chain.runs_natively)) {
      const std::string name = chain.name + "-" + path;
      std::vector<std::string> with = chain.settings;
      with.insert(with.end(), path_settings.begin(), path_settings.end());
      const Validated run = run_counted(folder, name, app, true, with);
      INFO(app.name << ", " << name << ":\n" << run.output);
      check_clean(run, alone);
      CHECK(run.output.find("ignored") == std::string::npos);  // the chain is the one asked for
      CHECK((run.output.find("the chain runs natively") != std::string::npos) == (path == "native"));
    }
  }
}

}  // namespace

TEST_CASE("validated: vkcube through no effect, bloom, bloom at strength 0 and an FX effect, on every path each can take",
          "[validation][vkcube]") {
  check_every_chain(vkcube());
}

TEST_CASE("validated: mpv's gpu output through every kind of chain, on every path each can take", "[validation][mpv]") {
  check_every_chain(mpv("gpu"));
}

TEST_CASE("validated: mpv's gpu-next output through every kind of chain, on every path each can take", "[validation][mpv]") {
  check_every_chain(mpv("gpu-next"));
}

TEST_CASE("validated: vkd3d-gears (Direct3D 12 through vkd3d) through every kind of chain, on every path each can take, ended "
          "at --quit-after",
          "[validation][vkd3d]") {
  check_every_chain(vkd3d_gears());
}

TEST_CASE("validated: an FX effect that fails at its first frame in vkcube, on every path: the frames pass through "
          "and vkcube ends normally",
          "[validation][vkcube]") {
  // The test grade's LUT texture is not there: its instance fails at the first frame (on the GL
  // paths once the chain has the frame, with the go-between filled and the GL's draws queued).
  ScratchFolder folder("vulkan-validation-failing");
  const Validated alone = run_counted(folder, "alone", vkcube(), false);
  REQUIRE(alone.exit_code == 0);
  for (const auto& [path, path_settings] : paths_for(true)) {
    const std::string name = "failing-" + path;
    std::vector<std::string> settings = {"PFX_FX_PATH=" PFX_FX_TESTS "/files/Grade.fx", "PFX_INJECT_CHAIN=fx_grade"};
    settings.insert(settings.end(), path_settings.begin(), path_settings.end());
    const Validated run = run_counted(folder, name, vkcube(), true, settings);
    INFO(name << ":\n" << run.output);
    CHECK(run.exit_code == 0);
    CHECK(run.output.find("frame 1: frames pass through from now on: effect 'fx_grade'") != std::string::npos);
    CHECK(messages_not_in(run.messages, alone.messages) == "");
  }
}

namespace {

// Replaces the file the way editors and pfx-view write one: a new file renamed over the old.
void replace_file(const std::string& path, const std::string& text) {
  std::ofstream(path + ".tmp") << text;
  std::filesystem::rename(path + ".tmp", path);
}

// A preset of bloom switched off while the application runs (its frames then go by with the
// chain idle) and on again: frames without passes and frames with them follow each other.
void check_preset_switched_live(const App& app) {
  ScratchFolder folder("vulkan-validation-live-" + app.name);
  const std::string preset = folder.file("look.json");
  const std::string on = R"({"pfx_preset": 1, "chain": [{"effect": "bloom"}]})";
  const std::string off = R"({"pfx_preset": 1, "chain": [{"effect": "bloom", "enabled": false}]})";
  std::ofstream(preset) << on;
  const Script switch_off_and_on = [&](pfx::test::ViewerProcess& process, bool with_pfx) {
    if (!with_pfx) return std::this_thread::sleep_for(std::chrono::seconds(2));
    wait_for_the_layer(process);
    replace_file(preset, off);
    CHECK_FALSE(process.wait_for_line("settings applied: chain bloom (off)", 20).empty());
    std::this_thread::sleep_for(std::chrono::seconds(1));  // frames with the chain idle
    replace_file(preset, on);
    CHECK_FALSE(process.wait_for_line("settings applied: chain bloom", 20).empty());
  };
  const Validated alone = run_session(folder, "alone", app, false, {}, switch_off_and_on);
  INFO(app.name << " alone:\n" << alone.output);
  REQUIRE(alone.exit_code == 0);
  check_clean(run_session(folder, "live", app, true, {"PFX_INJECT_PRESET=" + preset}, switch_off_and_on), alone);
}

}  // namespace

TEST_CASE("validated: a preset switched off and on again while vkcube runs", "[validation][vkcube][preset]") {
  check_preset_switched_live(vkcube());
}

TEST_CASE("validated: a preset switched off and on again while mpv plays", "[validation][mpv][preset]") {
  check_preset_switched_live(mpv("gpu"));
}

TEST_CASE("validated: a preset switched off and on again while vkd3d-gears runs", "[validation][vkd3d][preset]") {
  check_preset_switched_live(vkd3d_gears());
}

namespace {

// The window resized, hidden from the screen and shown again (what minimising does under X11 with
// no window manager), with bloom on.
void check_resized_and_minimised(const App& app) {
  ScratchFolder folder("vulkan-validation-window-" + app.name);
  const unsigned width = app.width * 2 / 3, height = app.height * 2 / 3;
  const Script resize_hide_show = [&](pfx::test::ViewerProcess& process, bool with_pfx) {
    // Presenting, as when a user resizes it (vkd3d-gears resized before its first frames asserts
    // now and then, without pfx too: it made no swapchain).
    if (with_pfx) wait_for_the_layer(process);
    std::this_thread::sleep_for(std::chrono::seconds(1));
    CHECK(pfx::test::resize_window(app.width, app.height, width, height));
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    CHECK(pfx::test::hide_window(width, height));
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    CHECK(pfx::test::show_window(width, height));
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
  };
  const std::vector<std::string> bloom = {"PFX_INJECT_CHAIN=bloom"};
  const Validated alone = run_session(folder, "alone", app, false, bloom, resize_hide_show, {width, height});
  INFO(app.name << " alone:\n" << alone.output);
  REQUIRE(alone.exit_code == 0);
  check_clean(run_session(folder, "window", app, true, bloom, resize_hide_show, {width, height}), alone);
  // The native path: the effect's instances made for the new size beside the old ones.
  const std::vector<std::string> relief = {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx", "PFX_INJECT_CHAIN=fx_relief"};
  check_clean(run_session(folder, "window-native", app, true, relief, resize_hide_show, {width, height}), alone);
}

}  // namespace

TEST_CASE("validated: vkcube's window resized, minimised and restored", "[validation][vkcube][window]") {
  check_resized_and_minimised(vkcube());
}

TEST_CASE("validated: vkd3d-gears' window resized, minimised and restored", "[validation][vkd3d][window]") {
  check_resized_and_minimised(vkd3d_gears());
}

TEST_CASE("validated: vkBasalt's CAS and pfx's bloom stacked either way, and an FX effect natively above it, ended "
          "at --quit-after with both layers' work in flight",
          "[validation][vkcube][vkbasalt]") {
  ScratchFolder folder("vulkan-validation-vkbasalt");
  std::ofstream(folder.file("vkBasalt.conf")) << "effects = cas\n";
  const std::vector<std::string> basalt = {"ENABLE_VKBASALT=1", "VKBASALT_CONFIG_FILE=" + folder.file("vkBasalt.conf")};
  App app = vkcube();
  app.counted.clear();  // ended by pfx's --quit-after
  const Validated alone = run_session(folder, "alone", app, false, basalt, [](auto&, bool) {
    std::this_thread::sleep_for(std::chrono::seconds(1));
  });
  INFO("vkcube and vkBasalt alone:\n" << alone.output);
  REQUIRE(alone.exit_code == 0);
  SECTION("pfx above vkBasalt (both implicit)") {
    std::vector<std::string> settings = basalt;
    settings.push_back("PFX_INJECT_CHAIN=bloom");
    check_clean(run_counted(folder, "above", app, true, settings), alone);
  }
  SECTION("pfx below vkBasalt (pfx's layer enabled as an explicit one, above the validation layer)") {
    pfx::test::write_explicit_manifest(folder);
    const std::string validation_folder = std::filesystem::path(PFX_VALIDATION_MANIFEST).parent_path();
    std::vector<std::string> settings = basalt;
    settings.insert(settings.end(), {"XDG_DATA_HOME=" + folder.path(),
                                     "VK_LAYER_PATH=" + folder.path() + ":" + validation_folder,
                                     "VK_INSTANCE_LAYERS=VK_LAYER_PFX_post_effects:VK_LAYER_KHRONOS_validation",
                                     "PFX_INJECT_CHAIN=bloom"});
    check_clean(run_counted(folder, "below", app, true, settings), alone);
  }
  SECTION("pfx natively above vkBasalt: an FX effect on the application's queue after vkBasalt's work") {
    std::vector<std::string> settings = basalt;
    settings.insert(settings.end(), {"PFX_FX_PATH=" PFX_LAYER_EFFECTS "/Relief.fx", "PFX_INJECT_CHAIN=fx_relief"});
    const Validated run = run_counted(folder, "above-native", app, true, settings);
    check_clean(run, alone);
    CHECK(run.output.find("the chain runs natively") != std::string::npos);
  }
}
