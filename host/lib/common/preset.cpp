#include "preset.hpp"
#include "reshade_preset.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"

namespace pfx::app {
namespace {

using Json = nlohmann::json;

// Throws PresetError with the member's path; caught once in parse_preset.
struct PresetError {
  std::string message;
};

[[noreturn]] void refuse(const std::string& member, const std::string& problem) {
  throw PresetError{member + ": " + problem};
}

void only_known_members(const Json& object, const std::string& where, const std::set<std::string>& known) {
  for (const auto& item : object.items())
    if (!known.count(item.key())) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      refuse(where + item.key(), "unknown member (known: " + list + ")");
    }
}

double finite_number(const Json& value, const std::string& member) {
  if (!value.is_number()) refuse(member, "must be a number");
  double number = value.get<double>();
  if (!std::isfinite(number)) refuse(member, "must be finite");
  return number;
}

std::array<double, 3> vector3(const Json& value, const std::string& member) {
  if (!value.is_array() || value.size() != 3) refuse(member, "must be an array of 3 numbers");
  std::array<double, 3> v{};
  for (size_t i = 0; i < 3; ++i) v[i] = finite_number(value[i], member + "[" + std::to_string(i) + "]");
  return v;
}

std::vector<PresetEffect> parse_chain(const Json& chain) {
  if (!chain.is_array()) refuse("chain", "must be an array of {\"effect\": ID, \"enabled\": BOOL}");
  std::vector<PresetEffect> effects;
  for (size_t i = 0; i < chain.size(); ++i) {
    const std::string where = "chain[" + std::to_string(i) + "]";
    const Json& item = chain[i];
    if (!item.is_object()) refuse(where, "must be an object {\"effect\": ID, \"enabled\": BOOL}");
    only_known_members(item, where + ".", {"effect", "enabled"});
    PresetEffect effect;
    if (!item.contains("effect") || !item["effect"].is_string() || item["effect"].get<std::string>().empty())
      refuse(where + ".effect", "must be an effect id");
    effect.id = item["effect"].get<std::string>();
    if (item.contains("enabled")) {
      if (!item["enabled"].is_boolean()) refuse(where + ".enabled", "must be true or false");
      effect.enabled = item["enabled"].get<bool>();
    }
    effects.push_back(effect);
  }
  return effects;
}

PresetCamera parse_camera(const Json& camera) {
  if (!camera.is_object()) refuse("camera", "must be an object");
  only_known_members(camera, "camera.", {"position", "target", "up", "fovy_degrees", "near", "far"});
  PresetCamera out;
  const int place_members = int(camera.contains("position")) + int(camera.contains("target")) + int(camera.contains("up"));
  if (place_members != 0 && place_members != 3) refuse("camera", "position, target and up go together");
  if (place_members == 3) {
    out.position = vector3(camera["position"], "camera.position");
    out.target = vector3(camera["target"], "camera.target");
    out.up = vector3(camera["up"], "camera.up");
    const auto& p = *out.position, &t = *out.target, &u = *out.up;
    const double d[3] = {t[0] - p[0], t[1] - p[1], t[2] - p[2]};
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) refuse("camera.target", "must differ from camera.position");
    // up must not be parallel to the view direction: their cross product must not vanish.
    const double c[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
    const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double un = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) <= 1e-9 * dn * un)
      refuse("camera.up", "must not be zero or parallel to the view direction");
  }
  if (camera.contains("fovy_degrees")) {
    double fovy = finite_number(camera["fovy_degrees"], "camera.fovy_degrees");
    if (!(fovy > 0 && fovy < 180)) refuse("camera.fovy_degrees", "must be between 0 and 180 degrees");
    out.fovy_degrees = fovy;
  }
  if (camera.contains("near")) {
    double near_plane = finite_number(camera["near"], "camera.near");
    if (!(near_plane > 0)) refuse("camera.near", "must be a positive distance");
    out.near_plane = near_plane;
  }
  if (camera.contains("far")) {
    const Json& far = camera["far"];
    if (far.is_string() && far.get<std::string>() == "inf") out.far_plane = INFINITY;
    else if (far.is_number()) out.far_plane = finite_number(far, "camera.far");
    else refuse("camera.far", "must be a number or \"inf\"");
  }
  if (out.near_plane && out.far_plane && !(*out.far_plane > *out.near_plane))
    refuse("camera.far", "must be greater than camera.near");
  return out;
}

void parse_display(const Json& display, Preset* out) {
  if (!display.is_object()) refuse("display", "must be an object");
  only_known_members(display, "display.", {"exposure_ev", "tone"});
  if (display.contains("exposure_ev")) out->exposure_ev = finite_number(display["exposure_ev"], "display.exposure_ev");
  if (display.contains("tone")) {
    if (!display["tone"].is_string()) refuse("display.tone", "must be a tone curve name");
    ToneCurve curve;
    std::string message;
    if (!parse_tone_curve(display["tone"].get<std::string>(), &curve, &message)) refuse("display.tone", message);
    out->tone = curve;
  }
}

}  // namespace

bool parse_preset(const std::string& json, Preset* out, std::string* error) {
  Json root;
  try {
    root = Json::parse(json);
  } catch (const Json::exception& e) {
    if (error) *error = std::string("not valid JSON: ") + e.what();
    return false;
  }
  try {
    if (!root.is_object()) refuse("preset", "must be a JSON object");
    only_known_members(root, "", {"pfx_preset", "chain", "parameters", "camera", "display", "source_definitions"});
    if (!root.contains("pfx_preset") || !root["pfx_preset"].is_number_integer())
      refuse("pfx_preset", "missing: a preset starts with \"pfx_preset\": " + std::to_string(kPresetVersion));
    const auto version = root["pfx_preset"].get<long long>();
    if (version != kPresetVersion)
      refuse("pfx_preset", "version " + std::to_string(version) + " is not supported (this program reads version " +
                               std::to_string(kPresetVersion) + ")");
    Preset preset;
    if (root.contains("chain")) preset.chain = parse_chain(root["chain"]);
    if (root.contains("parameters")) {
      if (!root["parameters"].is_object()) refuse("parameters", "must be an object of effects");
      preset.parameters_json = root["parameters"].dump();
    }
    if (root.contains("camera")) preset.camera = parse_camera(root["camera"]);
    if (root.contains("display")) parse_display(root["display"], &preset);
    if (root.contains("source_definitions")) {
      if (!root["source_definitions"].is_string()) refuse("source_definitions", "must be a string \"NAME=VALUE,FLAG\"");
      preset.source_definitions = root["source_definitions"].get<std::string>();
    }
    *out = std::move(preset);
    return true;
  } catch (const PresetError& e) {
    if (error) *error = e.message;
    return false;
  }
}

bool read_preset(const std::string& path, Preset* out, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = path + ": cannot open the preset";
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::string message;
  if (looks_like_reshade_preset(text.str())) {
    parse_reshade_preset(text.str(), out);
    return true;
  }
  if (!parse_preset(text.str(), out, &message)) {
    if (error) *error = path + ": " + message;
    return false;
  }
  return true;
}

std::string preset_to_json(const Preset& preset) {
  nlohmann::ordered_json root;
  root["pfx_preset"] = kPresetVersion;
  if (preset.chain) {
    root["chain"] = nlohmann::ordered_json::array();
    for (const auto& effect : *preset.chain) root["chain"].push_back({{"effect", effect.id}, {"enabled", effect.enabled}});
  }
  if (!preset.parameters_json.empty()) root["parameters"] = nlohmann::ordered_json::parse(preset.parameters_json);
  const PresetCamera& c = preset.camera;
  nlohmann::ordered_json camera = nlohmann::ordered_json::object();
  if (c.position && c.target && c.up) {
    camera["position"] = *c.position;
    camera["target"] = *c.target;
    camera["up"] = *c.up;
  }
  if (c.fovy_degrees) camera["fovy_degrees"] = *c.fovy_degrees;
  if (c.near_plane) camera["near"] = *c.near_plane;
  if (c.far_plane) camera["far"] = std::isinf(*c.far_plane) ? nlohmann::ordered_json("inf") : nlohmann::ordered_json(*c.far_plane);
  if (!camera.empty()) root["camera"] = camera;
  nlohmann::ordered_json display = nlohmann::ordered_json::object();
  if (preset.exposure_ev) display["exposure_ev"] = *preset.exposure_ev;
  if (preset.tone) display["tone"] = tone_curve_name(*preset.tone);
  if (!display.empty()) root["display"] = display;
  if (!preset.source_definitions.empty()) root["source_definitions"] = preset.source_definitions;
  return root.dump(2) + "\n";
}

bool write_preset(const std::string& path, const Preset& preset, std::string* error) {
  return write_text_atomically(path, preset_to_json(preset), error);
}

}  // namespace pfx::app
