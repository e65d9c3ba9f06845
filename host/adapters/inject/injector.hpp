// The injector's state in the application's process: the settings, the log, the plugins, one
// pipeline per GL context, the frame count. One instance, made at the first hooked call and
// never destroyed (an application may present from an atexit handler or a static destructor).
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_recipe.hpp"
#include "context_pipeline.hpp"
#include "inject_log.hpp"
#include "inject_settings.hpp"
#include "present_stats.hpp"
#include "preset_watch.hpp"
#include "timings_channel.hpp"
#include "window_system.hpp"

namespace pfx::inject {

class Injector {
 public:
  static Injector& instance();

  // Before the real present: runs the chain into the back buffer of the current context. Any
  // failure is logged once and that context's frames pass through from then on.
  void before_present(const PresentCall& call) noexcept;
  // After the real present: counts the frame, and ends the application after --quit-after.
  void after_present() noexcept;
  // Before the real destroy: forgets the context's pipeline (freeing its GL objects when the
  // context is current on this thread; otherwise they go with the context).
  void context_destroyed(WindowSystem system, void* context) noexcept;

 private:
  struct LoadedSettings {
    InjectSettings settings;
    std::vector<std::string> problems;  // variables that did not parse, said once in the log
  };
  static LoadedSettings load_settings();
  Injector();
  explicit Injector(LoadedSettings loaded);
  struct ContextEntry {
    std::unique_ptr<ContextPipeline> pipeline;  // null: frames of this context pass through
    uint64_t recipe_generation = 0;
    int number = 0;  // in the order contexts first presented, from 1, for the log
    std::string aside;  // without a pipeline: why its frames pass through
  };
  using ContextKey = std::pair<WindowSystem, void*>;

  void present(const PresentCall& call);
  bool load_plugins(WindowSystem system);
  void reread_preset_if_changed();
  // Logs that this frame's captures will not be written, and why.
  void say_captures_skipped(const std::string& why);
  // The current context's entry, its chain made ready for this present: at the context's first
  // present the plugins are loaded (once per process) and its pipeline built, or the reason it
  // passes through kept; at a later one the preset file is read again when it changed.
  ContextEntry& prepare_context_chain(const PresentCall& call, void* context);
  // Writes the frame times and frees the current context's pipeline; the caller then exits.
  void prepare_to_quit();

  std::mutex mutex_;
  const InjectSettings settings_;
  InjectLog log_;
  std::unique_ptr<host::PluginRegistry> registry_;
  bool plugins_refused_ = false;
  ChainRecipe recipe_;
  uint64_t recipe_generation_ = 0;  // 0: no recipe read yet
  PresetWatch preset_watch_;
  TimingsChannel timings_;
  std::map<ContextKey, ContextEntry> contexts_;
  // Pipelines of contexts destroyed while not current: their GL objects died with the context,
  // and their instances cannot be destroyed without it, so they are kept, unused.
  std::vector<std::unique_ptr<ContextPipeline>> orphans_;
  int contexts_seen_ = 0;
  uint64_t presented_ = 0;
  std::chrono::steady_clock::time_point first_present_;
  PresentStats stats_;
  double copy_pass_ms_ = 0;
  std::string chain_text_;
};

}  // namespace pfx::inject
