// Presets: a look saved to a JSON file - the effect chain, every parameter value, the camera and
// the display settings - so pfx-view can save it and pfx-render --preset can reproduce it.
//
//   {
//     "pfx_preset": 1,
//     "chain": [{"effect": "bloom", "enabled": true}, ...],
//     "parameters": {"bloom": {"threshold": 1.5, "mode": "chain"}},   (ParamStore::to_json's form)
//     "camera": {"position": [x, y, z], "target": [x, y, z], "up": [0, 1, 0],
//                "fovy_degrees": 45, "near": 0.1, "far": 1000},          ("far": "inf" for no far plane)
//     "display": {"exposure_ev": 0, "tone": "linear"},
//     "source_definitions": "NAME=VALUE,FLAG"
//   }
//
// "source_definitions" are preprocessor definitions for the effects made from source files (the
// FX plugin's), as a ReShade preset's PreprocessorDefinitions= line gives them
// (Chain::set_source_definitions): a pfx-view copy of a ReShade preset keeps them.
//
// Every member but "pfx_preset" is optional, and so is each camera and display field (position,
// target and up go together): a hand-written preset may hold only what it wants to change.
// Unknown members are refused, so a misspelt key is an error rather than silently ignored.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "tonemap.hpp"

namespace pfx::app {

constexpr int kPresetVersion = 1;

struct PresetEffect {
  std::string id;
  bool enabled = true;
};

struct PresetCamera {
  // Where the camera is and looks; meaningless for an image input (it has no place).
  std::optional<std::array<double, 3>> position, target, up;
  std::optional<double> fovy_degrees, near_plane, far_plane;  // far may be +infinity
};

struct Preset {
  std::optional<std::vector<PresetEffect>> chain;
  std::string parameters_json;  // a JSON object text, or empty for none
  // Values applied one by one after parameters_json ("effect.param=value"), each given by the
  // alternatives to try in turn; one none of whose alternatives applies is left out with a
  // warning, and the rest still apply. A ReShade preset's values come this way
  // (reshade_preset.hpp): it may name what no loaded effect has.
  std::vector<std::vector<std::string>> assignments;
  std::vector<std::string> notes;  // what the reader could not carry over, for the host to say
  // A ReShade preset: effects of its chain that are not loaded are left out with a warning instead
  // of failing the chain.
  bool from_reshade = false;
  // Preprocessor definitions for the effects made from source files, "NAME=VALUE,FLAG", or "" for
  // none: a ReShade preset's PreprocessorDefinitions, checked when applied.
  std::string source_definitions;
  PresetCamera camera;
  std::optional<double> exposure_ev;
  std::optional<ToneCurve> tone;
};

// Parses preset JSON; false with *error naming the member ("camera.near: must be a positive
// number"). Values are checked here as far as they can be without plugins: the effect ids and the
// parameter values are checked when applied (ParamStore::from_json, Chain::add).
bool parse_preset(const std::string& json, Preset* out, std::string* error);
// Reads and parses a file, a pfx JSON preset or a ReShade preset (.ini, reshade_preset.hpp);
// errors start with "PATH: ".
bool read_preset(const std::string& path, Preset* out, std::string* error);
std::string preset_to_json(const Preset& preset);
// Writes atomically (atomic_file.hpp).
bool write_preset(const std::string& path, const Preset& preset, std::string* error);

}  // namespace pfx::app
