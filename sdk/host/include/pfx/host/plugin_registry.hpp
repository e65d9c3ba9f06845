// Loads plugin libraries and keeps them: the loader half of libpfxhost (DESIGN.md §4).
// Every failure is a message "FILE: reason"; a bad plugin is refused whole and never takes the
// host or the other plugins down.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <pfx/pfx.h>

#include "pfx/host/api.hpp"
#include "pfx/host/log.hpp"

namespace pfx::host {

// Returns a GL entry point of the current context (eglGetProcAddress, glfwGetProcAddress...).
using GlProcLoader = std::function<pfx_gl_proc(const char* name)>;

struct Plugin;

struct EffectInfo {
  const pfx_effect_desc* desc = nullptr;
  const Plugin* plugin = nullptr;
};

// One loaded library. Owned by the registry; pointers stay valid until the registry dies.
struct Plugin {
  std::string path;
  std::string id, name, version;
  uint32_t abi_minor = 0;
  std::vector<const pfx_effect_desc*> effects;
  // The plugin's CPU references ("pfx.references/1"), or null when it ships none.
  const pfx_reference_factory* references = nullptr;
  // The services this plugin was given (host_data points back at the registry's record).
  const pfx_host* host = nullptr;
};

class PFX_HOST_API PluginRegistry {
 public:
  PluginRegistry(GlProcLoader gl_loader, LogSink log, std::string host_name = "libpfxhost");
  // Calls every plugin's deinit and unloads it. Destroy effect instances (the Chain) first.
  ~PluginRegistry();
  PluginRegistry(const PluginRegistry&) = delete;
  PluginRegistry& operator=(const PluginRegistry&) = delete;

  // Loads one library. On failure returns false, sets *error to "PATH: reason" and leaves the
  // registry as it was.
  bool load(const std::string& path, std::string* error);
  // Loads every *.so in a folder, in name order; returns the messages of those refused.
  std::vector<std::string> load_directory(const std::string& directory);
  // The folders to search: the explicit ones, then each entry of PFX_PLUGIN_PATH (':'-separated).
  static std::vector<std::string> search_path(const std::vector<std::string>& explicit_directories);
  // load_directory over search_path(explicit_directories); a missing folder is an error message.
  std::vector<std::string> load_search_path(const std::vector<std::string>& explicit_directories);

  const std::vector<std::unique_ptr<Plugin>>& plugins() const { return plugins_; }
  std::vector<EffectInfo> effects() const;  // in load order
  const EffectInfo* find_effect(const std::string& id) const;

  const LogSink& log() const { return log_; }
  const GlProcLoader& gl_loader() const { return gl_loader_; }

 // Internal: what the registry keeps per library (handle, entry, the pfx_host given to it).
  struct Record;

 private:
  GlProcLoader gl_loader_;
  LogSink log_;
  std::string host_name_;
  std::vector<std::unique_ptr<Plugin>> plugins_;
  std::vector<std::unique_ptr<Record>> records_;  // parallel to plugins_
  std::vector<EffectInfo> effect_index_;
};

}  // namespace pfx::host
