// The layer's settings and log: pfx-inject's variables (docs/inject.md), read by pfx-inject's own
// code (inject_settings.hpp), so a Vulkan application is set up exactly as an OpenGL one.
#include <cstdlib>
#include <memory>

#include "inject_log.hpp"
#include "inject_settings.hpp"
#include "layer_calls.hpp"

extern char** environ;

namespace pfx::vulkan_layer {
namespace {

struct Loaded {
  inject::InjectSettings settings;
  std::string chain, set, preset, plugin_path;
  BridgeSettings bridge;
  std::unique_ptr<inject::InjectLog> log;
};

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

Loaded& loaded() {
  // Read once, at the first use (a present or a log line), never freed: a thread of the
  // application may still present at exit.
  static Loaded* once = [] {
    auto* l = new Loaded;
    std::vector<std::string> problems;
    l->settings = inject::settings_from_environment([](const char* name) -> const char* { return std::getenv(name); },
                                                    &problems);
    l->log = std::make_unique<inject::InjectLog>(l->settings.log_file);
    std::vector<std::string> names;
    for (char** entry = environ; *entry; ++entry) names.push_back(std::string(*entry).substr(0, std::string(*entry).find('=')));
    for (const auto& problem : inject::unknown_variables(names)) problems.push_back(problem);
    for (const auto& problem : problems) l->log->line("(vulkan) ignored " + problem);
    if (l->settings.chain) {
      l->chain = l->settings.chain->empty() ? "none" : joined(*l->settings.chain, ",");
      l->bridge.chain = l->chain.c_str();
    }
    l->set = joined(l->settings.sets, ";");
    l->bridge.set = l->set.c_str();
    l->preset = l->settings.preset;
    l->bridge.preset = l->preset.empty() ? nullptr : l->preset.c_str();
    l->bridge.transfer = l->settings.transfer == app::Transfer::LINEAR ? "linear" : "srgb";
    l->plugin_path = joined(l->settings.plugin_dirs, ":");
    l->bridge.plugin_path = l->plugin_path.empty() ? nullptr : l->plugin_path.c_str();
    return l;
  }();
  return *once;
}

}  // namespace

const BridgeSettings& bridge_settings() { return loaded().bridge; }

const inject::InjectSettings& layer_inject_settings() { return loaded().settings; }

void log_line(const std::string& message) { loaded().log->line("(vulkan) " + message); }

void log_once(const std::string& key, const std::string& message) { loaded().log->once(key, "(vulkan) " + message); }

}  // namespace pfx::vulkan_layer
