#include "inject_settings.hpp"

#include <charconv>
#include <cmath>
#include <locale>
#include <limits>
#include <sstream>

#include "cli_text.hpp"

namespace pfx::inject {
namespace {

std::vector<std::string> lines_of(const std::string& text) { return app::split_list(text, '\n'); }

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// Shortest text that reads back as the same double.
std::string number_text(double value) {
  if (std::isinf(value)) return "inf";
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(17);
  out << value;
  return out.str();
}

}  // namespace

bool parse_capture(const std::string& text, Capture* out, std::string* error) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos || colon + 1 >= text.size()) {
    *error = "capture '" + text + "': expected N:PREFIX or all:PREFIX (with %d in PREFIX)";
    return false;
  }
  Capture capture;
  const std::string when = text.substr(0, colon);
  capture.prefix = text.substr(colon + 1);
  const size_t percent = capture.prefix.find('%');
  if (when == "all") {
    capture.every_frame = true;
    if (percent == std::string::npos || capture.prefix.compare(percent, 2, "%d") != 0 ||
        capture.prefix.find('%', percent + 1) != std::string::npos) {
      *error = "capture '" + text + "': all:PREFIX needs exactly one %d in PREFIX (the frame number)";
      return false;
    }
  } else {
    long long frame = 0;
    if (!app::parse_count(when, &frame) || frame < 1) {
      *error = "capture '" + text + "': the frame must be a number from 1 or 'all'";
      return false;
    }
    if (percent != std::string::npos) {
      *error = "capture '" + text + "': '%' is only for all:PREFIX";
      return false;
    }
    capture.frame = static_cast<uint64_t>(frame);
  }
  *out = capture;
  return true;
}

bool parse_frame_list(const std::string& text, std::vector<uint64_t>* out, std::string* error) {
  std::vector<uint64_t> frames;
  for (const auto& item : app::split_list(text)) {
    long long frame = 0;
    if (!app::parse_count(item, &frame) || frame < 1) {
      *error = "'" + item + "' is not a frame number from 1";
      return false;
    }
    frames.push_back(static_cast<uint64_t>(frame));
  }
  if (frames.empty()) {
    *error = "expected frame numbers, e.g. 500,5000";
    return false;
  }
  *out = std::move(frames);
  return true;
}

bool parse_depth_plane(const std::string& text, bool allow_infinity, double* out, std::string* error) {
  if (allow_infinity && text == "inf") {
    *out = std::numeric_limits<double>::infinity();
    return true;
  }
  // from_chars, not strtod: inside an application the C locale may use a decimal comma.
  double value = 0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || status != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value <= 0) {
    *error = "depth plane '" + text + "': expected a positive number of metres" + (allow_infinity ? " or inf" : "");
    return false;
  }
  *out = value;
  return true;
}

bool check_depth_planes(double near_plane, double far_plane, std::string* error) {
  if (near_plane < far_plane) return true;
  *error = "the near depth plane (" + number_text(near_plane) + ") must be closer than the far one (" +
           number_text(far_plane) + ")";
  return false;
}

InjectSettings settings_from_environment(EnvLookup lookup, std::vector<std::string>* problems) {
  InjectSettings settings;
  auto text = [&](const char* name) -> std::string {
    const char* value = lookup(name);
    return value ? value : "";
  };
  auto complain = [&](const char* name, const std::string& message) {
    problems->push_back(std::string(name) + ": " + message);
  };
  std::string error;
  if (const char* chain = lookup(env::kChain)) {
    const std::string list = chain;
    settings.chain = list == "none" ? std::vector<std::string>{} : app::split_list(list);
  }
  settings.preset = text(env::kPreset);
  settings.sets = lines_of(text(env::kSet));
  settings.plugin_dirs = app::split_list(text(env::kPlugins), ':');
  double near_plane = settings.depth_near, far_plane = settings.depth_far;
  if (!text(env::kDepthNear).empty() && !parse_depth_plane(text(env::kDepthNear), false, &near_plane, &error))
    complain(env::kDepthNear, error);
  if (!text(env::kDepthFar).empty() && !parse_depth_plane(text(env::kDepthFar), true, &far_plane, &error))
    complain(env::kDepthFar, error);
  if (check_depth_planes(near_plane, far_plane, &error)) {
    settings.depth_near = near_plane;
    settings.depth_far = far_plane;
  } else {
    complain(env::kDepthNear, error);
  }
  if (!text(env::kTransfer).empty() && !app::parse_transfer(text(env::kTransfer), &settings.transfer, &error))
    complain(env::kTransfer, error);
  for (const auto& item : lines_of(text(env::kCapture))) {
    Capture capture;
    if (parse_capture(item, &capture, &error)) settings.captures.push_back(capture);
    else complain(env::kCapture, error);
  }
  if (!text(env::kQuitAfter).empty()) {
    long long count = 0;
    if (app::parse_count(text(env::kQuitAfter), &count)) settings.quit_after = static_cast<uint64_t>(count);
    else complain(env::kQuitAfter, "'" + text(env::kQuitAfter) + "' is not a frame count");
  }
  if (!text(env::kFromFrame).empty()) {
    long long frame = 0;
    if (app::parse_count(text(env::kFromFrame), &frame) && frame >= 1) settings.from_frame = static_cast<uint64_t>(frame);
    else complain(env::kFromFrame, "'" + text(env::kFromFrame) + "' is not a frame number from 1");
  }
  auto flag = [&](const char* name) {
    const std::string value = text(name);
    if (value.empty() || value == "0") return false;
    if (value == "1") return true;
    complain(name, "'" + value + "' is not 1 or 0");
    return false;
  };
  settings.dry_run = flag(env::kDryRun);
  settings.bypass = flag(env::kBypass);
  settings.log_file = text(env::kLog);
  settings.stats_file = text(env::kStats);
  settings.timings_file = text(env::kTimings);
  if (!text(env::kResourcesAt).empty()) {
    // One item that does not parse is left out; the others stay.
    for (const auto& item : app::split_list(text(env::kResourcesAt))) {
      std::vector<uint64_t> frame;
      if (parse_frame_list(item, &frame, &error)) settings.resources_at.push_back(frame[0]);
      else complain(env::kResourcesAt, error);
    }
  }
  return settings;
}

std::vector<std::string> unknown_variables(const std::vector<std::string>& names) {
  std::vector<std::string> problems;
  for (const auto& name : names) {
    if (name.rfind("PFX_INJECT_", 0) != 0) continue;
    bool known = false;
    for (const char* variable : env::kAll) known |= name == variable;
    if (!known) problems.push_back(name + ": not a pfx-inject variable (docs/inject.md lists them)");
  }
  return problems;
}

std::vector<std::string> settings_to_environment(const InjectSettings& settings) {
  std::vector<std::string> vars;
  auto put = [&](const char* name, const std::string& value) { vars.push_back(std::string(name) + "=" + value); };
  const InjectSettings defaults;
  if (settings.chain) put(env::kChain, settings.chain->empty() ? "none" : join(*settings.chain, ","));
  if (!settings.preset.empty()) put(env::kPreset, settings.preset);
  if (!settings.sets.empty()) put(env::kSet, join(settings.sets, "\n"));
  if (!settings.plugin_dirs.empty()) put(env::kPlugins, join(settings.plugin_dirs, ":"));
  if (settings.depth_near != defaults.depth_near) put(env::kDepthNear, number_text(settings.depth_near));
  if (settings.depth_far != defaults.depth_far) put(env::kDepthFar, number_text(settings.depth_far));
  if (settings.transfer != defaults.transfer) put(env::kTransfer, app::transfer_name(settings.transfer));
  std::vector<std::string> captures;
  for (const auto& capture : settings.captures)
    captures.push_back((capture.every_frame ? std::string("all") : std::to_string(capture.frame)) + ":" + capture.prefix);
  if (!captures.empty()) put(env::kCapture, join(captures, "\n"));
  if (settings.quit_after) put(env::kQuitAfter, std::to_string(settings.quit_after));
  if (settings.from_frame != defaults.from_frame) put(env::kFromFrame, std::to_string(settings.from_frame));
  if (settings.dry_run) put(env::kDryRun, "1");
  if (settings.bypass) put(env::kBypass, "1");
  if (!settings.log_file.empty()) put(env::kLog, settings.log_file);
  if (!settings.stats_file.empty()) put(env::kStats, settings.stats_file);
  if (!settings.timings_file.empty()) put(env::kTimings, settings.timings_file);
  std::vector<std::string> frames;
  for (uint64_t frame : settings.resources_at) frames.push_back(std::to_string(frame));
  if (!frames.empty()) put(env::kResourcesAt, join(frames, ","));
  return vars;
}

std::vector<std::string> capture_prefixes(const std::vector<Capture>& captures, uint64_t frame) {
  std::vector<std::string> prefixes;
  for (const auto& capture : captures) {
    if (capture.every_frame) {
      std::string prefix = capture.prefix;
      prefix.replace(prefix.find("%d"), 2, std::to_string(frame));
      prefixes.push_back(prefix);
    } else if (capture.frame == frame) {
      prefixes.push_back(capture.prefix);
    }
  }
  return prefixes;
}

std::vector<SkippedCapture> skipped_captures(const std::vector<Capture>& captures, uint64_t frame,
                                             const std::string& why, const std::string& suffix) {
  const std::string at = "frame " + std::to_string(frame) + ": ";
  std::vector<SkippedCapture> out;
  for (const auto& capture : captures) {
    if (capture.every_frame)
      out.push_back({"capture " + capture.prefix + suffix + why,
                     at + "captures all:" + capture.prefix + suffix + " are not written while " + why});
    else if (capture.frame == frame)
      out.push_back({"", at + "capture " + capture.prefix + suffix + " not written: " + why});
  }
  return out;
}

}  // namespace pfx::inject
