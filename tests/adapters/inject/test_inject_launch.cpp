// What pfx-inject refuses before the application starts, the exit codes it returns, and what the
// library does with settings a user set by hand (the same rule for every variable).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>


#include "inject_run.hpp"

using namespace pfx::test;

namespace {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
}

bool exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

// pfx-inject ARGS -- sh -c 'touch MARKER; exit CODE': whether the application ran is whether the
// marker exists.
RunResult run_marker_app(const std::vector<std::string>& args, const std::string& marker, int code = 0) {
  std::vector<std::string> argv = {PFX_INJECT};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"--", "sh", "-c", "touch '" + marker + "'; exit " + std::to_string(code)});
  return run_program(argv, 60);
}

}  // namespace

TEST_CASE("a bad chain, --set or capture, or a preset that does not read, is refused before the application starts") {
  ScratchFolder folder("refused");
  const std::string half_saved = folder.file("half-saved.json");
  write_text(half_saved, R"({"pfx_preset": 1, "chain": [{"effect": "bloom"}, )");
  struct Case {
    std::vector<std::string> args;
    std::string named;  // what the message must name
  };
  const std::vector<Case> cases = {
      {{"--chain", "nosuch"}, "effect 'nosuch' is not loaded"},
      {{"--chain", "bloom,nosuch"}, "effect 'nosuch' is not loaded"},
      {{"--set", "bloom.threshold=abc"}, "'abc' is not a number"},
      {{"--set", "bloom.nosuch=1"}, "has no parameter 'nosuch'"},
      {{"--set", "nosuch.x=1"}, "unknown effect 'nosuch'"},
      {{"--set", "garbage"}, "--set garbage: expected EFFECT.PARAM=VALUE"},
      {{"--chain", "bloom", "--set", "bloom#2.strength=2"}, "there is no bloom#2"},
      {{"--preset", folder.file("missing.json")}, "missing.json"},
      {{"--preset", half_saved}, "half-saved.json: not valid JSON"},
      {{"--capture", "3:" + folder.file("no-such-folder/shot")}, "no-such-folder does not exist"},
      {{"--quit-after", "3", "--capture", "5:" + folder.file("shot")}, "ends after frame 3"},
      {{"--from-frame", "2", "--capture", "1:" + folder.file("shot")}, "before --from-frame 2"},
      {{"--depth-near", "5", "--depth-far", "2"}, "must be closer"},
      {{"--transfer", "gamma"}, "--transfer"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"--plugins", PFX_PLUGIN_OUTPUT_DIR};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const std::string marker = folder.file("ran");
    const RunResult run = run_marker_app(args, marker);
    INFO(c.args.back() << ": " << run.output);
    CHECK(run.exit_code == 240);
    CHECK(run.output.find(c.named) != std::string::npos);
    CHECK_FALSE(exists(marker));
  }
  // No plugin at all is a set-up error, not a usage one.
  std::filesystem::create_directory(folder.file("empty"));
  const RunResult none = run_marker_app({"--plugins", folder.file("empty")}, folder.file("ran"));
  INFO(none.output);
  CHECK(none.exit_code == 241);
  CHECK(none.output.find("no effect plugins found") != std::string::npos);
  CHECK_FALSE(exists(folder.file("ran")));
}

TEST_CASE("the application's own exit code passes through unchanged, and one that cannot start gives 242") {
  ScratchFolder folder("exit-codes");
  for (int code : {0, 1, 2, 7, 127}) {
    const RunResult run = run_marker_app({"--plugins", PFX_PLUGIN_OUTPUT_DIR, "--chain", "bloom"}, folder.file("ran"), code);
    INFO(run.output);
    CHECK(run.exit_code == code);
    CHECK(exists(folder.file("ran")));
  }
  const RunResult missing = run_program({PFX_INJECT, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--", folder.file("no-such-program")});
  INFO(missing.output);
  CHECK(missing.exit_code == 242);
  CHECK(missing.output.find("cannot run") != std::string::npos);
}

namespace {

// The library alone, as a game launcher's LD_PRELOAD would run it (no launcher checks), on
// glxgears; `variables` are NAME=VALUE.
RunResult run_by_hand(const std::vector<std::string>& variables, bool frozen_clock) {
  std::vector<std::string> argv = {"/usr/bin/env"};
  std::string preload = std::string("LD_PRELOAD=") + PFX_INJECT_LIBRARY;
#if defined(__SANITIZE_ADDRESS__)
  // The sanitized library in an application that is not: AddressSanitizer's runtime goes first,
  // and the application's own allocations are not ours to judge (pfx-inject does the same).
  preload = "LD_PRELOAD=" + pfx::test::sanitizer_runtime() + ":" + PFX_INJECT_LIBRARY;
  const char* asan_options = std::getenv("ASAN_OPTIONS");
  argv.push_back(std::string("ASAN_OPTIONS=") + (asan_options ? asan_options : "") + ":detect_leaks=0");
#endif
  if (frozen_clock) {
    argv.push_back("FAKETIME=2020-01-01 00:00:00");
    preload += std::string(":") + PFX_FAKETIME_LIBRARY;
  }
  argv.push_back(preload);
  argv.push_back(std::string("PFX_INJECT_PLUGINS=") + PFX_PLUGIN_OUTPUT_DIR);
  argv.insert(argv.end(), variables.begin(), variables.end());
  argv.push_back(PFX_GLXGEARS);
  return run_program(argv, 60);
}

const char* const kHandChain = "PFX_INJECT_CHAIN=nosuch,bloom";
const char* const kHandSets = "PFX_INJECT_SET=garbage\nbloom.threshold=abc\nbloom.strength=3\nbloom.threshold=0.3";

}  // namespace

TEST_CASE("variables set by hand: what does not apply is named and left out, the rest runs") {
  ScratchFolder folder("by-hand");
  const std::string log = folder.file("by-hand.log");
  const RunResult run = run_by_hand({kHandChain, kHandSets, "PFX_INJECT_CAPTURE=3:" + folder.file("missing/shot"),
                                     "PFX_INJECT_QUIT_AFTER=3", "PFX_INJECT_DRY_RUNN=1", "PFX_INJECT_LOG=" + log},
                                    false);
  const std::string text = read_text_file(log);
  INFO(run.output << text);
  REQUIRE(run.exit_code == 0);
  CHECK(text.find("ignored PFX_INJECT_CHAIN: effect 'nosuch' is not loaded") != std::string::npos);
  CHECK(text.find("ignored PFX_INJECT_SET: 'garbage' is not of the form effect.param=value") != std::string::npos);
  CHECK(text.find("ignored PFX_INJECT_SET: bloom.threshold: 'abc' is not a number") != std::string::npos);
  CHECK(text.find("ignored PFX_INJECT_DRY_RUNN: not a pfx-inject variable") != std::string::npos);
  CHECK(text.find("chain: bloom") != std::string::npos);
  // Each capture file that failed is named.
  for (const char* file : {"shot.app.exr", "shot.out.exr", "shot.png"})
    CHECK(text.find("capture " + folder.file("missing/") + file + " not written") != std::string::npos);
}

TEST_CASE("variables set by hand: the assignments that apply give the frame the launcher gives for them") {
  ScratchFolder folder("by-hand-frame");
  const RunResult run = run_by_hand({kHandChain, kHandSets, "PFX_INJECT_CAPTURE=3:" + folder.file("hand"),
                                     "PFX_INJECT_QUIT_AFTER=3", "PFX_INJECT_LOG=" + folder.file("hand.log")},
                                    true);
  INFO(run.output << read_text_file(folder.file("hand.log")));
  REQUIRE(run.exit_code == 0);
  const InjectRun reference = run_injected(folder, "reference",
                                           {"--chain", "bloom", "--set", "bloom.strength=3", "--set",
                                            "bloom.threshold=0.3", "--quit-after", "3", "--capture",
                                            "3:" + folder.file("reference")},
                                           {PFX_GLXGEARS});
  INFO(reference.result.output << reference.log);
  REQUIRE(reference.result.exit_code == 0);
  CHECK(same_pixels(read_png_file(folder.file("hand.png")), read_png_file(folder.file("reference.png"))));
  // And they changed it: the dry run's frame is the application's own.
  const InjectRun dry = run_injected(folder, "dry", {"--dry-run", "--chain", "bloom", "--quit-after", "3", "--capture",
                                                     "3:" + folder.file("dry")},
                                     {PFX_GLXGEARS});
  REQUIRE(dry.result.exit_code == 0);
  CHECK_FALSE(same_pixels(read_png_file(folder.file("hand.png")), read_png_file(folder.file("dry.png"))));
}

TEST_CASE("with no effect on, or only no-ops, no present goes through the chain, and with bloom every one does") {
  ScratchFolder folder("untouched");
  // The count of presents whose frame was copied in, run and copied out, from the frame times
  // the library writes for --bench.
  auto through_chain = [&](const std::string& name, std::vector<std::string> variables) {
    const std::string stats = folder.file(name + ".json");
    variables.insert(variables.end(), {"PFX_INJECT_STATS=" + stats, "PFX_INJECT_QUIT_AFTER=6"});
    const RunResult run = run_by_hand(variables, true);
    const std::string text = read_text_file(stats);
    INFO(name << ": " << run.output << text);
    REQUIRE(run.exit_code == 0);
    REQUIRE(text.find("\"frames\": 6,") != std::string::npos);
    const size_t at = text.find("\"frames_through_chain\": ");
    REQUIRE(at != std::string::npos);
    return std::stoi(text.substr(at + std::strlen("\"frames_through_chain\": ")));
  };
  CHECK(through_chain("none", {"PFX_INJECT_CHAIN=none"}) == 0);
  CHECK(through_chain("off", {"PFX_INJECT_CHAIN=bloom", "PFX_INJECT_SET=bloom.strength=0"}) == 0);
  CHECK(through_chain("bloom", {"PFX_INJECT_CHAIN=bloom"}) == 6);
}
