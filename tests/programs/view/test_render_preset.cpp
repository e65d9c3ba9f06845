// pfx-render --preset: what a preset sets, what the command line overrides, and the errors.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "view_process.hpp"

namespace fs = std::filesystem;
using pfx::test::run_program;

namespace {

struct PresetFiles {
  fs::path dir = fs::temp_directory_path() / ("pfx-render-preset-" + std::to_string(::getpid()));
  PresetFiles() { fs::create_directories(dir); }
  ~PresetFiles() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

// pfx-render --json over a 16x8 demo image with the fixture plugins; the report as JSON.
nlohmann::json render_report(const std::vector<std::string>& args, int expected_exit = 0) {
  std::vector<std::string> argv = {PFX_RENDER, "--plugins", PFX_TEST_PLUGIN_DIR, "--demo-image", "--size", "16x8", "--json"};
  argv.insert(argv.end(), args.begin(), args.end());
  auto r = run_program(argv);
  INFO(r.output);
  REQUIRE(r.exit_code == expected_exit);
  if (expected_exit != 0) return nlohmann::json(r.output);
  return nlohmann::json::parse(r.output.substr(r.output.find('{')));
}

}  // namespace

TEST_CASE("pfx-render takes the chain and values from a preset, and the command line overrides them", "[render][preset]") {
  PresetFiles files;
  const std::string preset = files.write("p.json", R"({"pfx_preset": 1,
    "chain": [{"effect": "boxblur", "enabled": true}, {"effect": "gain", "enabled": false}],
    "parameters": {"gain": {"gain": 4}, "boxblur": {"radius": 2}}})");
  auto report = render_report({"--preset", preset});
  CHECK(report["effects"] == nlohmann::json::parse(R"(["boxblur"])"));
  CHECK(report["effects_skipped"] == nlohmann::json::parse(R"(["gain"])"));  // in the chain, switched off
  // The demo image's mean goes up 4x with gain 4: compare with gain on through --chain.
  const double plain = render_report({"--chain", "boxblur", "--set", "boxblur.radius=2"})["output"]["mean"][0];
  const double gained = render_report({"--preset", preset, "--chain", "boxblur,gain"})["output"]["mean"][0];
  CHECK(gained == Approx(4 * plain).epsilon(0.01));
  // --set wins over the preset's value.
  const double set = render_report({"--preset", preset, "--chain", "boxblur,gain", "--set", "gain.gain=2"})["output"]["mean"][0];
  CHECK(set == Approx(2 * plain).epsilon(0.01));
}

TEST_CASE("pfx-render refuses a bad preset with exit 3 and a message naming the file and member", "[render][preset][errors]") {
  PresetFiles files;
  auto message = render_report({"--preset", (files.dir / "none.json").string()}, 3).get<std::string>();
  CHECK(message.find("none.json: cannot open the preset") != std::string::npos);
  const std::string bad_camera = files.write("camera.json", R"({"pfx_preset": 1, "camera": {"fovy_degrees": 0}})");
  message = render_report({"--preset", bad_camera}, 3).get<std::string>();
  CHECK(message.find("camera.json: camera.fovy_degrees: must be between 0 and 180 degrees") != std::string::npos);
  const std::string bad_value = files.write("value.json", R"({"pfx_preset": 1, "parameters": {"gain": {"gain": "loud"}}})");
  message = render_report({"--preset", bad_value}, 3).get<std::string>();
  CHECK(message.find("value.json: parameters: gain.gain: 'loud' is not a number") != std::string::npos);
  const std::string bad_chain = files.write("chain.json", R"({"pfx_preset": 1, "chain": [{"effect": "nosuch"}]})");
  message = render_report({"--preset", bad_chain}, 4).get<std::string>();
  CHECK(message.find("unknown effect 'nosuch'") != std::string::npos);
}
