// The live control panel: pfx-inject --panel starts pfx-view --attach beside the application, in
// its scripted mode here. A value set in the panel reaches the running application, whose next
// frames are then exactly those of a run started with that value; the panel shows the per-pass
// times the injected chain writes; ending pfx-inject ends the application and the panel.
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <regex>
#include <thread>

#include "inject_run.hpp"

using namespace pfx::test;

TEST_CASE("a value set in the live panel changes the running application's next frames accordingly") {
  ScratchFolder folder("panel");
  const std::string frames = folder.file("frames");
  std::filesystem::create_directory(frames);
  std::vector<std::string> argv = {"/usr/bin/env"};
#if defined(__SANITIZE_ADDRESS__)
  const char* asan_options = std::getenv("ASAN_OPTIONS");  // see run_injected
  argv.push_back(std::string("ASAN_OPTIONS=") + (asan_options ? asan_options : "") + ":verify_asan_link_order=0");
#endif
  // The panel edits bloom.strength at its 30th frame, once the application is well under way.
  argv.insert(argv.end(), {"FAKETIME=2020-01-01 00:00:00", std::string("LD_PRELOAD=") + PFX_FAKETIME_LIBRARY,
                           PFX_INJECT, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--panel", "--panel-option", "--frames",
                           "--panel-option", "200", "--panel-option", "--edit", "--panel-option",
                           "30:bloom.strength=4", "--chain", "bloom", "--capture", "all:" + frames + "/f%d", "--",
                           PFX_GLXGEARS, "-geometry", "64x64"});
  ViewerProcess app(argv);
  const std::string applied = app.wait_for_line("preset applied: chain bloom", 60);
  INFO(app.output());
  REQUIRE_FALSE(applied.empty());
  std::smatch match;
  REQUIRE(std::regex_search(applied, match, std::regex("frame ([0-9]+): preset applied")));
  const int changed = std::stoi(match[1].str());
  REQUIRE(changed > 2);
  // The panel read the chain's pass times (the clock is stopped, so they read 0 ms here).
  const std::string times_line = "pfx-view: the application's pass times";
  if (app.output().find(times_line) == std::string::npos) app.wait_for_line(times_line, 60);
  const size_t times = app.output().find(times_line);
  REQUIRE(times != std::string::npos);
  CHECK(app.output().find("bloom/composite", times) != std::string::npos);
  const std::string after = frames + "/f" + std::to_string(changed + 1) + ".png";
  for (int i = 0; i < 600 && !std::filesystem::exists(after); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  // Ending pfx-inject ends the application (SIGTERM passed on) and the panel.
  app.send(SIGTERM);
  CHECK(app.wait_exit(30) == 128 + SIGTERM);
  const std::string before = frames + "/f" + std::to_string(changed - 1) + ".png";
  REQUIRE(std::filesystem::exists(after));
  CHECK_FALSE(same_pixels(read_png_file(before), read_png_file(after)));
  const InjectRun reference = run_injected(folder, "reference",
                                           {"--chain", "bloom", "--set", "bloom.strength=4", "--quit-after", "3",
                                            "--capture", "3:" + folder.file("reference")},
                                           {PFX_GLXGEARS, "-geometry", "64x64"});
  INFO(reference.result.output << reference.log);
  REQUIRE(reference.result.exit_code == 0);
  CHECK(same_pixels(read_png_file(after), read_png_file(folder.file("reference.png"))));
}
