// The settings pfx-inject passes to libpfxinject.so: what the options and the variables accept,
// and that the library reads back exactly what the launcher wrote; and the depth judgement, which
// needs no GL either.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "depth_judge.hpp"
#include "inject_options.hpp"
#include "inject_settings.hpp"

using namespace pfx::inject;

namespace {

std::map<std::string, std::string> variables;
const char* lookup(const char* name) {
  auto found = variables.find(name);
  return found == variables.end() ? nullptr : found->second.c_str();
}

InjectSettings through_environment(const InjectSettings& settings, std::vector<std::string>* problems) {
  variables.clear();
  for (const auto& variable : settings_to_environment(settings)) {
    const size_t equals = variable.find('=');
    variables[variable.substr(0, equals)] = variable.substr(equals + 1);
  }
  return settings_from_environment(lookup, problems);
}

bool parse(const std::vector<std::string>& args, InjectOptions* options, std::string* error) {
  return parse_inject_options(args, options, error);
}

}  // namespace

TEST_CASE("every option reaches the library through the environment unchanged") {
  InjectOptions options;
  std::string error;
  REQUIRE(parse({"--preset", "look.json", "--chain", "bloom,dof", "--set", "bloom.threshold=0.5", "--set",
                 "bloom.tint=1,0.5,0.25", "--plugins", "/a", "--plugins", "/b", "--depth-near", "0.05", "--depth-far",
                 "inf", "--transfer", "linear", "--capture", "12:shot", "--capture", "all:f%d", "--quit-after", "40",
                 "--from-frame", "3", "--dry-run", "--log", "inject.log", "--", "glxgears", "-info"},
                &options, &error));
  CHECK(options.command == std::vector<std::string>{"glxgears", "-info"});
  std::vector<std::string> problems;
  const InjectSettings read = through_environment(options.settings, &problems);
  CHECK(problems.empty());
  REQUIRE(read.chain);
  CHECK(*read.chain == std::vector<std::string>{"bloom", "dof"});
  CHECK(read.preset == "look.json");
  // A value with commas survives: assignments travel one per line.
  CHECK(read.sets == std::vector<std::string>{"bloom.threshold=0.5", "bloom.tint=1,0.5,0.25"});
  CHECK(read.plugin_dirs == std::vector<std::string>{"/a", "/b"});
  CHECK(read.depth_near == 0.05);
  CHECK(std::isinf(read.depth_far));
  CHECK(read.transfer == Transfer::LINEAR);
  REQUIRE(read.captures.size() == 2);
  CHECK(read.captures[0].frame == 12);
  CHECK(read.captures[0].prefix == "shot");
  CHECK(read.captures[1].every_frame);
  CHECK(read.captures[1].prefix == "f%d");
  CHECK(read.quit_after == 40);
  CHECK(read.from_frame == 3);
  CHECK(read.dry_run);
  CHECK(read.log_file == "inject.log");
}

TEST_CASE("the chain 'none' is an empty chain, and no chain option leaves the choice to the preset") {
  InjectOptions options;
  std::string error;
  std::vector<std::string> problems;
  REQUIRE(parse({"--chain", "none", "--", "app"}, &options, &error));
  const InjectSettings none = through_environment(options.settings, &problems);
  REQUIRE(none.chain);
  CHECK(none.chain->empty());
  InjectOptions defaults;
  REQUIRE(parse({"--", "app"}, &defaults, &error));
  CHECK_FALSE(through_environment(defaults.settings, &problems).chain);
}

TEST_CASE("pfx-inject refuses what it cannot do, naming the option") {
  InjectOptions options;
  std::string error;
  CHECK_FALSE(parse({"--chain", "bloom"}, &options, &error));
  CHECK(error.find("no application given") != std::string::npos);
  CHECK_FALSE(parse({"--capture", "0:x", "--", "app"}, &options, &error));
  CHECK(error.find("--capture") != std::string::npos);
  CHECK_FALSE(parse({"--capture", "all:x", "--", "app"}, &options, &error));
  CHECK(error.find("%d") != std::string::npos);
  CHECK_FALSE(parse({"--capture", "3:x%d", "--", "app"}, &options, &error));
  CHECK_FALSE(parse({"--depth-near", "5", "--depth-far", "2", "--", "app"}, &options, &error));
  CHECK(error.find("closer") != std::string::npos);
  CHECK_FALSE(parse({"--depth-near", "inf", "--", "app"}, &options, &error));
  CHECK_FALSE(parse({"--transfer", "gamma", "--", "app"}, &options, &error));
  CHECK_FALSE(parse({"--bench", "5", "--", "app"}, &options, &error));
  CHECK(error.find("at least 20") != std::string::npos);
  CHECK_FALSE(parse({"--bench", "50", "--quit-after", "3", "--", "app"}, &options, &error));
  CHECK_FALSE(parse({"--set", "bloom", "--", "app"}, &options, &error));
  CHECK_FALSE(parse({"--frobnicate", "--", "app"}, &options, &error));
  CHECK(error.find("unknown option '--frobnicate'") != std::string::npos);
}

TEST_CASE("a variable that does not parse is reported and its default kept, never fatal") {
  variables = {{env::kTransfer, "gamma"},     {env::kQuitAfter, "-3"},  {env::kDepthNear, "0,1"},
               {env::kCapture, "x:y\n4:ok"}, {env::kDepthFar, "nan"}, {env::kFromFrame, "0"}};
  std::vector<std::string> problems;
  const InjectSettings read = settings_from_environment(lookup, &problems);
  CHECK(problems.size() == 6);
  CHECK(read.transfer == Transfer::SRGB);
  CHECK(read.quit_after == 0);
  CHECK(read.depth_near == 0.1);
  CHECK(read.depth_far == 1000);
  CHECK(read.from_frame == 1);
  REQUIRE(read.captures.size() == 1);
  CHECK(read.captures[0].frame == 4);
}

TEST_CASE("a flag that is not 1 or 0 is reported, and a misspelt variable name is named") {
  variables = {{env::kDryRun, "yes"}, {env::kBypass, "0"}};
  std::vector<std::string> problems;
  const InjectSettings read = settings_from_environment(lookup, &problems);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] == "PFX_INJECT_DRY_RUN: 'yes' is not 1 or 0");
  CHECK_FALSE(read.dry_run);
  const auto unknown = unknown_variables({"PFX_INJECT_CHAIN", "PFX_INJECT_CHIAN", "HOME", "PFX_PLUGIN_PATH"});
  REQUIRE(unknown.size() == 1);
  CHECK(unknown[0].rfind("PFX_INJECT_CHIAN: not a pfx-inject variable", 0) == 0);
}

TEST_CASE("depth judged before it is trusted: one value, the far plane, reversed-Z, and a drawn scene") {
  using pfx::inject::DepthFinding;
  using pfx::inject::judge_depth;
  // A scene: the far plane behind, something drawn in front.
  const std::vector<float> scene = {1, 1, 0.93f, 0.95f, 0.97f, 1, 1, 1};
  const DepthFinding drawn = judge_depth(scene.data(), scene.size());
  CHECK(drawn.usable());
  CHECK(drawn.what == "37.5 % of the frame drawn, from 0.93 to 1");
  // Cleared and never drawn (the application draws into a framebuffer of its own).
  const std::vector<float> far(64, 1.0f);
  CHECK(judge_depth(far.data(), far.size()).kind == DepthFinding::ONE_VALUE);
  CHECK(judge_depth(far.data(), far.size()).what == "one value everywhere (1: the far plane, nothing drawn into it)");
  const std::vector<float> middle(64, 0.5f);
  CHECK(judge_depth(middle.data(), middle.size()).what == "one value everywhere (0.5)");
  const std::vector<float> zero(64, 0.0f);
  CHECK(judge_depth(zero.data(), zero.size()).kind == DepthFinding::ONE_VALUE);
  // Reversed-Z leaves 0 where nothing is drawn, and nothing at 1.
  const std::vector<float> reversed = {0, 0, 0.02f, 0.05f, 0, 0.3f};
  CHECK(judge_depth(reversed.data(), reversed.size()).kind == DepthFinding::REVERSED);
  // Non-finite values count as not drawn; none finite is nothing to judge.
  const std::vector<float> nan(4, NAN);
  CHECK(judge_depth(nan.data(), nan.size()).kind == DepthFinding::NO_VALUES);
  CHECK_FALSE(judge_depth(nullptr, 0).usable());
  const std::vector<float> with_nan = {NAN, 1, 0.9f, INFINITY};
  CHECK(judge_depth(with_nan.data(), with_nan.size()).usable());
}

TEST_CASE("the options --resources-at and --panel: parsed, passed on, and refused where they do not fit") {
  InjectOptions options;
  std::string error;
  REQUIRE(parse({"--resources-at", "500,5000", "--panel", "--panel-option", "--window", "--panel-option", "400x600",
                 "--", "app"},
                &options, &error));
  CHECK(options.panel);
  CHECK(options.panel_options == std::vector<std::string>{"--window", "400x600"});
  std::vector<std::string> problems;
  const InjectSettings read = through_environment(options.settings, &problems);
  CHECK(problems.empty());
  CHECK(read.resources_at == std::vector<uint64_t>{500, 5000});
  CHECK_FALSE(parse({"--resources-at", "500,x", "--", "app"}, &options, &error));
  CHECK(error.find("'x' is not a frame number") != std::string::npos);
  CHECK_FALSE(parse({"--panel-option", "--window", "--", "app"}, &options, &error));
  CHECK(error.find("--panel-option goes with --panel") != std::string::npos);
  CHECK_FALSE(parse({"--panel", "--bench", "50", "--", "app"}, &options, &error));
  // By hand: the frame that does not parse is named and left out, the other kept.
  variables = {{env::kResourcesAt, "10,zero,30"}};
  const InjectSettings by_hand = settings_from_environment(lookup, &problems);
  CHECK(by_hand.resources_at == std::vector<uint64_t>{10, 30});
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].rfind("PFX_INJECT_RESOURCES_AT: 'zero'", 0) == 0);
}
