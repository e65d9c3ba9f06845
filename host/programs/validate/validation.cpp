#include "validation.hpp"

#include <chrono>
#include <functional>
#include <map>

#include "child_process.hpp"
#include "dirty_state_check.hpp"
#include "heap_check.hpp"
#include "plugin_checks.hpp"
#include "process_state_check.hpp"
#include "render_checks.hpp"

namespace pfx::validate {
namespace {

using Body = std::function<void(CheckReporter&)>;

// Runs one check in a child and turns what it reported into a result.
CheckResult run_check(const std::string& check, const std::string& effect, const Body& body,
                      const ValidationSettings& settings, ChildReport* raw = nullptr) {
  CheckResult result;
  result.check = check;
  result.effect = effect;
  const auto start = std::chrono::steady_clock::now();
  ChildReport child = run_in_child(body, settings.timeout_s);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.problems = child.problems;
  for (const auto& [key, value] : child.facts) {
    if (key == "set") result.random_sets.push_back(value);
    if (key == "heap_growth_bytes") result.heap_growth_bytes = std::stoll(value);
  }
  if (!child.stdout_text.empty()) {
    std::string quoted = child.stdout_text.substr(0, 200);
    for (size_t at = 0; (at = quoted.find('\n', at)) != std::string::npos; at += 2) quoted.replace(at, 1, "\\n");
    result.problems.push_back("wrote " + std::to_string(child.stdout_text.size()) +
                              " bytes to stdout (a plugin must never print): '" + quoted + "'");
  }
  const std::string abnormal = child.abnormal_end();
  if (!abnormal.empty()) {
    std::string message = abnormal;
    if (!child.stderr_text.empty()) message += "; its stderr ended with: " + child.stderr_text;
    result.problems.push_back(message);
  }
  result.status = child.end == ChildReport::End::Signalled || child.end == ChildReport::End::Exited ? Status::Crash
                  : child.end == ChildReport::End::TimedOut                                       ? Status::Timeout
                  : result.problems.empty()                                                       ? Status::Pass
                                                                                                  : Status::Fail;
  // A check that could not measure here says so: shown as skipped with its reason, never as a pass.
  const std::string skip = child.fact("skip");
  if (result.status == Status::Pass && !skip.empty()) {
    result.status = Status::Skip;
    result.problems.push_back("not run: " + skip);
  }
  if (raw) *raw = std::move(child);
  return result;
}

CheckResult skipped(const std::string& check, const std::string& effect, const std::string& why) {
  CheckResult result;
  result.check = check;
  result.effect = effect;
  result.status = Status::Skip;
  result.problems.push_back("not run: " + why);
  return result;
}

}  // namespace

const char* status_word(Status status) {
  switch (status) {
    case Status::Pass: return "pass";
    case Status::Fail: return "FAIL";
    case Status::Crash: return "CRASH";
    case Status::Timeout: return "TIMEOUT";
    case Status::Skip: return "skip";
  }
  return "?";
}

bool PluginResult::passed() const {
  for (const CheckResult& check : checks)
    if (check.status != Status::Pass && check.status != Status::Skip) return false;
  return true;
}

const std::vector<std::string>& plugin_check_names() {
  static const std::vector<std::string> names = {"load", "entry", "init/deinit", "factories", "process state",
                                                 "unique ids"};
  return names;
}

const std::vector<std::string>& effect_check_names() {
  static const std::vector<std::string> names = {"descriptors", "create/destroy", "defaults", "random params", "resize",
                                                    "8-bit frames", "dirty state", "heap growth"};
  return names;
}

PluginResult validate_plugin(const std::string& path, const ValidationSettings& settings) {
  PluginResult plugin;
  plugin.path = path;
  ChildReport raw;

  plugin.checks.push_back(run_check("load", "", [&](CheckReporter& r) { check_load(path, r); }, settings));
  if (plugin.checks.back().status != Status::Pass) {
    for (const char* check : {"entry", "init/deinit", "factories", "process state"})
      plugin.checks.push_back(skipped(check, "", "the plugin does not load"));
    return plugin;
  }
  plugin.checks.push_back(run_check("entry", "", [&](CheckReporter& r) { check_entry(path, r); }, settings, &raw));
  plugin.plugin_id = raw.fact("plugin_id");
  plugin.name = raw.fact("name");
  plugin.version = raw.fact("version");
  plugin.checks.push_back(run_check("init/deinit", "", [&](CheckReporter& r) { check_init_deinit(path, r); }, settings));
  plugin.checks.push_back(run_check("factories", "", [&](CheckReporter& r) { check_factories(path, r); }, settings, &raw));
  for (const auto& [key, value] : raw.facts)
    if (key == "effect") plugin.effects.push_back(value);
  plugin.checks.push_back(
      run_check("process state", "", [&](CheckReporter& r) { check_process_state(path, r); }, settings));

  for (const std::string& effect : plugin.effects) {
    plugin.checks.push_back(
        run_check("descriptors", effect, [&](CheckReporter& r) { check_descriptors(path, effect, r); }, settings));
    plugin.checks.push_back(
        run_check("create/destroy", effect, [&](CheckReporter& r) { check_create_destroy(path, effect, r); }, settings));
    plugin.checks.push_back(
        run_check("defaults", effect, [&](CheckReporter& r) { check_defaults(path, effect, r); }, settings));
    plugin.checks.push_back(run_check(
        "random params", effect, [&](CheckReporter& r) { check_random(path, effect, settings.seed, settings.runs, r); },
        settings));
    plugin.checks.push_back(run_check("resize", effect, [&](CheckReporter& r) { check_resize(path, effect, r); }, settings));
    plugin.checks.push_back(
        run_check("8-bit frames", effect, [&](CheckReporter& r) { check_display_frame(path, effect, r); }, settings));
    plugin.checks.push_back(
        run_check("dirty state", effect, [&](CheckReporter& r) { check_dirty_state(path, effect, r); }, settings));
    plugin.checks.push_back(
        run_check("heap growth", effect, [&](CheckReporter& r) { check_heap_growth(path, effect, r); }, settings));
  }
  return plugin;
}

void check_unique_ids(std::vector<PluginResult>* results) {
  std::map<std::string, std::string> plugin_ids, effect_ids;  // id -> the file that had it first
  for (PluginResult& plugin : *results) {
    CheckResult check;
    check.check = "unique ids";
    if (!plugin.plugin_id.empty() && !plugin_ids.emplace(plugin.plugin_id, plugin.path).second)
      check.problems.push_back("plugin id '" + plugin.plugin_id + "' is also the id of " + plugin_ids[plugin.plugin_id]);
    for (const std::string& effect : plugin.effects)
      if (!effect_ids.emplace(effect, plugin.path).second)
        check.problems.push_back("effect id '" + effect + "' is also an effect of " + effect_ids[effect]);
    check.status = check.problems.empty() ? Status::Pass : Status::Fail;
    // After "factories": the ids come from there.
    auto at = plugin.checks.begin();
    while (at != plugin.checks.end() && at->effect.empty()) ++at;
    plugin.checks.insert(at, check);
  }
}

}  // namespace pfx::validate
