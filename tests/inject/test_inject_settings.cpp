// The settings pfx-inject passes to libpfxinject.so: what the options and the variables accept,
// and that the library reads back exactly what the launcher wrote.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

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
