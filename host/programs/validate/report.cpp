#include "report.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace pfx::validate {
namespace {

// Per check in the text report: one broken pass can fail every render.
constexpr size_t kProblemsShown = 4;

const CheckResult* find(const PluginResult& plugin, const std::string& check, const std::string& effect) {
  for (const CheckResult& result : plugin.checks)
    if (result.check == check && result.effect == effect) return &result;
  return nullptr;
}

std::string pad(const std::string& text, size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

std::string table(const PluginResult& plugin) {
  std::vector<std::string> columns = {""};  // "" is the plugin column
  columns.insert(columns.end(), plugin.effects.begin(), plugin.effects.end());
  size_t check_width = 16, cell_width = 8;
  for (const std::string& effect : plugin.effects) cell_width = std::max(cell_width, effect.size() + 2);

  std::string text = pad("check", check_width) + pad("plugin", cell_width);
  for (const std::string& effect : plugin.effects) text += pad(effect, cell_width);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  text += "\n";
  std::vector<std::string> rows = plugin_check_names();
  rows.insert(rows.end(), effect_check_names().begin(), effect_check_names().end());
  for (const std::string& row : rows) {
    std::string line = pad(row, check_width);
    bool any = false;
    for (const std::string& column : columns) {
      const CheckResult* result = find(plugin, row, column);
      any |= result != nullptr;
      line += pad(result ? status_word(result->status) : "-", cell_width);
    }
    if (any) {
      while (!line.empty() && line.back() == ' ') line.pop_back();
      text += line + "\n";
    }
  }
  return text;
}

}  // namespace

std::string report_text(const std::vector<PluginResult>& results, const ValidationSettings& settings) {
  std::string text;
  int checks = 0, failed = 0;
  for (const PluginResult& plugin : results) {
    text += "plugin " + plugin.path;
    if (!plugin.plugin_id.empty()) text += " (" + plugin.plugin_id + " " + plugin.version + ")";
    text += "\n" + table(plugin);
    for (const CheckResult& check : plugin.checks) {
      ++checks;
      if (check.status == Status::Pass) continue;
      if (check.status != Status::Skip) ++failed;
      const std::string where = check.effect.empty() ? check.check : check.effect + " / " + check.check;
      const std::string prefix = "  " + std::string(status_word(check.status)) + " " + where + ": ";
      for (size_t i = 0; i < check.problems.size() && i < kProblemsShown; ++i) text += prefix + check.problems[i] + "\n";
      if (check.problems.size() > kProblemsShown)
        text += prefix + "and " + std::to_string(check.problems.size() - kProblemsShown) + " more (--json lists all)\n";
    }
    text += "\n";
  }
  char summary[160];
  std::snprintf(summary, sizeof summary, "%d of %d checks failed (seed %llu, %d random parameter sets per effect)\n",
                failed, checks, static_cast<unsigned long long>(settings.seed), settings.runs);
  return text + summary;
}

std::string report_json(const std::vector<PluginResult>& results, const ValidationSettings& settings) {
  nlohmann::ordered_json root;
  root["seed"] = settings.seed;
  root["runs"] = settings.runs;
  bool passed = true;
  root["plugins"] = nlohmann::ordered_json::array();
  for (const PluginResult& plugin : results) {
    nlohmann::ordered_json p;
    p["path"] = plugin.path;
    p["id"] = plugin.plugin_id;
    p["name"] = plugin.name;
    p["version"] = plugin.version;
    p["effects"] = plugin.effects;
    p["passed"] = plugin.passed();
    passed &= plugin.passed();
    p["checks"] = nlohmann::ordered_json::array();
    for (const CheckResult& check : plugin.checks) {
      nlohmann::ordered_json c;
      c["check"] = check.check;
      c["effect"] = check.effect.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(check.effect);
      c["status"] = status_word(check.status);
      c["problems"] = check.problems;
      if (!check.random_sets.empty()) c["random_sets"] = check.random_sets;
      if (check.heap_growth_bytes) c["heap_growth_bytes"] = *check.heap_growth_bytes;
      c["seconds"] = check.seconds;
      p["checks"].push_back(std::move(c));
    }
    root["plugins"].push_back(std::move(p));
  }
  root["passed"] = passed;
  return root.dump(2) + "\n";
}

}  // namespace pfx::validate
