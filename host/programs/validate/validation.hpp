// What pfx-validate does for a list of plugin files: every check in its own child process, in
// order, with the effect checks for each effect the factories check found. The results are plain
// data for report.hpp to print.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pfx::validate {

enum class Status { Pass, Fail, Crash, Timeout, Skip };
const char* status_word(Status status);  // "pass", "FAIL", "CRASH", "TIMEOUT", "skip"

struct CheckResult {
  std::string check;   // "load", "descriptors", ...
  std::string effect;  // empty for a check of the whole plugin
  Status status = Status::Pass;
  std::vector<std::string> problems;  // why it failed (or why it was skipped)
  std::vector<std::string> random_sets;  // "random": the parameter sets tried, as --set text
  std::optional<long long> heap_growth_bytes;  // "heap growth": what the measured cycles added
  double seconds = 0;
};

struct PluginResult {
  std::string path;
  std::string plugin_id, name, version;
  std::vector<std::string> effects;
  std::vector<CheckResult> checks;
  // No check failed, crashed or timed out (a check skipped, with its reason, is no failure).
  bool passed() const;
};

struct ValidationSettings {
  uint64_t seed = 1;
  int runs = 8;
  double timeout_s = 120;
};

// The checks of the whole plugin and those of each effect, in the order they run.
const std::vector<std::string>& plugin_check_names();
const std::vector<std::string>& effect_check_names();

PluginResult validate_plugin(const std::string& path, const ValidationSettings& settings);
// Plugin ids and effect ids must be unique across all the plugins validated together (a host
// refuses the second one); adds a "unique ids" check to each result.
void check_unique_ids(std::vector<PluginResult>* results);

}  // namespace pfx::validate
