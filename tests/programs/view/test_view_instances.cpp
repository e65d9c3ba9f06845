// An effect twice in the viewer's chain: a preset naming bloom#2, --set bloom#2 on top, the saved
// preset holding each instance's values under its name, and pfx-render reproducing the picture.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "view_process.hpp"

namespace fs = std::filesystem;
using pfx::test::compare_png;
using pfx::test::run_program;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-view-instances-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

void run_ok(const std::string& program, std::vector<std::string> args) {
  std::vector<std::string> argv = {program, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--demo", "--size", "160x90"};
  argv.insert(argv.end(), args.begin(), args.end());
  auto r = run_program(argv);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
}

// Two blooms around a glare, each with its own look.
const char* const kTwoBlooms = R"({
  "pfx_preset": 1,
  "chain": [{"effect": "bloom"}, {"effect": "glare"}, {"effect": "bloom"}],
  "parameters": {"bloom": {"strength": 0.3}, "bloom#2": {"strength": 2, "mode": "gaussian"}}
})";

}  // namespace

TEST_CASE("a preset with two instances of one effect round-trips through the viewer and pfx-render",
          "[view][window][preset][instances]") {
  Scratch scratch;
  std::ofstream(scratch / "two.json") << kTwoBlooms;
  run_ok(PFX_VIEW, {"--preset", scratch / "two.json", "--set", "bloom#2.threshold=0.5", "--frames", "2",
                    "--screenshot", scratch / "view.png", "--save-preset", scratch / "saved.json"});
  std::ifstream in(scratch / "saved.json");
  const auto saved = nlohmann::json::parse(in);
  CHECK(saved["chain"] == nlohmann::json::parse(R"([{"effect": "bloom", "enabled": true},
      {"effect": "glare", "enabled": true}, {"effect": "bloom", "enabled": true}])"));
  const auto& parameters = saved["parameters"];
  CHECK(parameters["bloom"]["strength"] == 0.3);
  CHECK(parameters["bloom"]["mode"] == "chain");
  CHECK(parameters["bloom#2"]["strength"] == 2);
  CHECK(parameters["bloom#2"]["mode"] == "gaussian");
  CHECK(parameters["bloom#2"]["threshold"] == 0.5);
  CHECK_FALSE(parameters.contains("bloom#1"));
  CHECK_FALSE(parameters.contains("bloom#3"));

  run_ok(PFX_RENDER, {"--preset", scratch / "saved.json", "--out", scratch / "saved.png"});
  auto d = compare_png(scratch / "view.png", scratch / "saved.png");
  CHECK(d.max <= 1);
  CHECK(d.mean <= 0.1);
  // The second bloom's values are in the picture: with the first's values for both it differs.
  run_ok(PFX_RENDER, {"--chain", "bloom,glare,bloom", "--set", "bloom.strength=0.3", "--set",
                      "bloom#2.strength=0.3", "--out", scratch / "alike.png"});
  CHECK(compare_png(scratch / "saved.png", scratch / "alike.png").mean > 1.0);
}
