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

TEST_CASE("pfx-render refuses a preset that does not read with exit 3 and a message naming the file and member", "[render][preset][errors]") {
  PresetFiles files;
  auto message = render_report({"--preset", (files.dir / "none.json").string()}, 3).get<std::string>();
  CHECK(message.find("none.json: cannot open the preset") != std::string::npos);
  const std::string bad_camera = files.write("camera.json", R"({"pfx_preset": 1, "camera": {"fovy_degrees": 0}})");
  message = render_report({"--preset", bad_camera}, 3).get<std::string>();
  CHECK(message.find("camera.json: camera.fovy_degrees: must be between 0 and 180 degrees") != std::string::npos);
}

TEST_CASE("pfx-render leaves out what a preset names that is not loaded or does not fit, in one warning, and runs the rest",
          "[render][preset][errors]") {
  PresetFiles files;
  const std::string preset = files.write("mixed.json", R"({"pfx_preset": 1,
    "chain": [{"effect": "nosuch"}, {"effect": "gain"}],
    "parameters": {"gain": {"gain": "loud", "nosuch": 1}, "boxblur": {"radius": 2}, "other": {"x": 1}}})");
  std::vector<std::string> argv = {PFX_RENDER, "--plugins", PFX_TEST_PLUGIN_DIR, "--demo-image", "--size", "16x8", "--json", "--preset", preset};
  auto r = run_program(argv);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("warning:") == r.output.rfind("warning:"));
  CHECK(r.output.find("mixed.json: left out: nosuch (not loaded), gain.gain ('loud' is not a number), gain.nosuch (no such "
                      "parameter), other.x (not loaded)") != std::string::npos);
  const auto report = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  // The chain is gain alone; it keeps its default (1), a no-op the plan skips, and the picture is
  // that of the chain with gain alone.
  CHECK(report["effects"].empty());
  CHECK(report["effects_skipped"] == nlohmann::json::parse(R"(["gain"])"));
  const double plain = render_report({"--chain", "gain"})["output"]["mean"][0];
  CHECK(report["output"]["mean"][0] == Approx(plain).epsilon(1e-6));

  // A farm job that wants all of it or nothing: --strict refuses the same preset, naming the same.
  const std::string refused = render_report({"--preset", preset, "--strict"}, 3).get<std::string>();
  CHECK(refused.find("mixed.json: left out: nosuch (not loaded)") != std::string::npos);
  CHECK(refused.find("(--strict)") != std::string::npos);
}
