// Presets (host/lib/common/preset.hpp): every member read and written back, and a clear error naming
// the member for every kind of bad preset; a ReShade preset's PreprocessorDefinitions kept through
// pfx-view's JSON copy.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "preset.hpp"
#include "reshade_preset.hpp"

namespace fs = std::filesystem;
using namespace pfx::app;

namespace {

const char* const kFullPreset = R"({
  "pfx_preset": 1,
  "chain": [{"effect": "bloom", "enabled": true}, {"effect": "gain", "enabled": false}, {"effect": "dof"}],
  "parameters": {"bloom": {"threshold": 1.5, "mode": "chain"}, "gain": {"gain": 2}},
  "camera": {"position": [1, 2, 3], "target": [0, 0.5, 0], "up": [0, 1, 0],
             "fovy_degrees": 50, "near": 0.25, "far": "inf"},
  "display": {"exposure_ev": -1.5, "tone": "aces"},
  "source_definitions": "PFX_LEVEL=0.75,FLAG"
})";

std::string parse_error(const std::string& json) {
  Preset preset;
  std::string error;
  CHECK_FALSE(parse_preset(json, &preset, &error));
  return error;
}

}  // namespace

TEST_CASE("a preset with every member is read as written", "[preset]") {
  Preset p;
  std::string error;
  INFO(error);
  REQUIRE(parse_preset(kFullPreset, &p, &error));
  REQUIRE(p.chain);
  REQUIRE(p.chain->size() == 3);
  CHECK((*p.chain)[0].id == "bloom");
  CHECK((*p.chain)[0].enabled);
  CHECK_FALSE((*p.chain)[1].enabled);
  CHECK((*p.chain)[2].enabled);  // "enabled" left out means on
  CHECK(p.parameters_json == R"({"bloom":{"mode":"chain","threshold":1.5},"gain":{"gain":2}})");
  CHECK(*p.camera.position == std::array<double, 3>{1, 2, 3});
  CHECK(*p.camera.target == std::array<double, 3>{0, 0.5, 0});
  CHECK(*p.camera.fovy_degrees == 50);
  CHECK(*p.camera.near_plane == 0.25);
  CHECK(std::isinf(*p.camera.far_plane));
  CHECK(*p.exposure_ev == -1.5);
  CHECK(*p.tone == ToneCurve::Aces);
  CHECK(p.source_definitions == "PFX_LEVEL=0.75,FLAG");
}

TEST_CASE("a preset written and read back is the same preset", "[preset]") {
  Preset p;
  std::string error;
  REQUIRE(parse_preset(kFullPreset, &p, &error));
  const std::string text = preset_to_json(p);
  Preset q;
  INFO(text);
  REQUIRE(parse_preset(text, &q, &error));
  CHECK(preset_to_json(q) == text);
  CHECK(text.find("\"far\": \"inf\"") != std::string::npos);

  // Only what it holds: an empty preset writes only its version.
  CHECK(preset_to_json(Preset{}) == "{\n  \"pfx_preset\": 1\n}\n");
}

TEST_CASE("a preset file appears whole or not at all", "[preset]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-preset-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Preset p;
  std::string error;
  REQUIRE(parse_preset(kFullPreset, &p, &error));
  const std::string path = (dir / "look.json").string();
  REQUIRE(write_preset(path, p, &error));
  Preset read;
  REQUIRE(read_preset(path, &read, &error));
  CHECK(preset_to_json(read) == preset_to_json(p));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // no temporary left

  CHECK_FALSE(write_preset((dir / "missing" / "look.json").string(), p, &error));
  CHECK(error.find("cannot write") != std::string::npos);
  CHECK_FALSE(read_preset((dir / "none.json").string(), &read, &error));
  CHECK(error == (dir / "none.json").string() + ": cannot open the preset");
  std::ofstream(dir / "bad.json") << "{\"pfx_preset\": 1, \"camera\": {\"near\": -1}}";
  CHECK_FALSE(read_preset((dir / "bad.json").string(), &read, &error));
  CHECK(error == (dir / "bad.json").string() + ": camera.near: must be a positive distance");
  fs::remove_all(dir);
}

TEST_CASE("bad presets are refused with the member named", "[preset][errors]") {
  CHECK(parse_error("not json").rfind("not valid JSON", 0) == 0);
  CHECK(parse_error("[1, 2]") == "preset: must be a JSON object");
  CHECK(parse_error("{}") == "pfx_preset: missing: a preset starts with \"pfx_preset\": 1");
  CHECK(parse_error(R"({"pfx_preset": 2})") == "pfx_preset: version 2 is not supported (this program reads version 1)");
  CHECK(parse_error(R"({"pfx_preset": 1, "paramters": {}})") ==
        "paramters: unknown member (known: camera, chain, display, parameters, pfx_preset, source_definitions)");
  CHECK(parse_error(R"({"pfx_preset": 1, "source_definitions": ["A=1"]})") ==
        "source_definitions: must be a string \"NAME=VALUE,FLAG\"");
  CHECK(parse_error(R"({"pfx_preset": 1, "chain": "bloom"})").rfind("chain: must be an array", 0) == 0);
  CHECK(parse_error(R"({"pfx_preset": 1, "chain": [{"enabled": true}]})") == "chain[0].effect: must be an effect id");
  CHECK(parse_error(R"({"pfx_preset": 1, "chain": [{"effect": "bloom", "enabled": 1}]})") ==
        "chain[0].enabled: must be true or false");
  CHECK(parse_error(R"({"pfx_preset": 1, "parameters": [1]})") == "parameters: must be an object of effects");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, 0, 1]}})") ==
        "camera: position, target and up go together");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, 0, 1], "target": [0, 0, 1], "up": [0, 1, 0]}})") ==
        "camera.target: must differ from camera.position");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 3]}})") ==
        "camera.up: must not be zero or parallel to the view direction");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 0]}})") ==
        "camera.up: must not be zero or parallel to the view direction");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, "a", 1], "target": [0, 0, 0], "up": [0, 1, 0]}})") ==
        "camera.position[1]: must be a number");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"position": [0, 1], "target": [0, 0, 0], "up": [0, 1, 0]}})") ==
        "camera.position: must be an array of 3 numbers");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"fovy_degrees": 180}})") ==
        "camera.fovy_degrees: must be between 0 and 180 degrees");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"fovy_degrees": 0}})") ==
        "camera.fovy_degrees: must be between 0 and 180 degrees");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"near": 0}})") == "camera.near: must be a positive distance");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"near": 1, "far": 1}})") == "camera.far: must be greater than camera.near");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"far": "infinity"}})") == "camera.far: must be a number or \"inf\"");
  CHECK(parse_error(R"({"pfx_preset": 1, "camera": {"fov": 40}})").rfind("camera.fov: unknown member", 0) == 0);
  CHECK(parse_error(R"({"pfx_preset": 1, "display": {"tone": "filmic"}})") ==
        "display.tone: unknown tone curve 'filmic' (choose one of: linear, reinhard, aces)");
  CHECK(parse_error(R"({"pfx_preset": 1, "display": {"exposure_ev": "2"}})") == "display.exposure_ev: must be a number");
  // JSON has no NaN or infinity literal, and a number too large for a double is no valid JSON.
  CHECK(parse_error(R"({"pfx_preset": 1, "display": {"exposure_ev": 1e999}})").rfind("not valid JSON", 0) == 0);
}

TEST_CASE("a ReShade preset's PreprocessorDefinitions are kept, also in its JSON copy", "[preset][reshade]") {
  const std::string ini =
      "PreprocessorDefinitions= PFX_LEVEL=0.75,RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=1 \n"
      "Techniques=Level@Level.fx\n"
      "TechniqueSorting=Level@Level.fx\n";
  Preset p;
  std::string error;
  REQUIRE(looks_like_reshade_preset(ini));
  parse_reshade_preset(ini, &p);
  // As written (the line trimmed): the plugin that applies them reads the list.
  CHECK(p.source_definitions == "PFX_LEVEL=0.75,RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=1");
  CHECK(p.notes.empty());
  REQUIRE(p.chain);
  CHECK((*p.chain)[0].id == "fx_level");

  // pfx-view saves its look as PRESET.ini.pfx.json: the definitions travel with it.
  const std::string json = preset_to_json(p);
  Preset copy;
  INFO(json);
  REQUIRE(parse_preset(json, &copy, &error));
  CHECK(copy.source_definitions == p.source_definitions);

  Preset none;
  parse_reshade_preset("PreprocessorDefinitions=\nTechniques=Level@Level.fx\n", &none);
  CHECK(none.source_definitions.empty());
  CHECK(preset_to_json(none).find("source_definitions") == std::string::npos);
}
