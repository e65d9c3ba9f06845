// Loads plugin libraries and keeps them: the loader half of libpfxhost (docs/architecture.md).
// Every failure is a message "FILE: reason"; a bad plugin is refused whole and never takes the
// host or the other plugins down.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <pfx/pfx.h>

#include "pfx/host/api.hpp"
#include "pfx/host/log.hpp"
#include "pfx/host/thread_pool.hpp"

namespace pfx::host {

// Returns a GL entry point of the current context (eglGetProcAddress, glfwGetProcAddress...).
using GlProcLoader = std::function<pfx_gl_proc(const char* name)>;

struct Plugin;

struct EffectInfo {
  const pfx_effect_desc* desc = nullptr;
  const Plugin* plugin = nullptr;
};

struct ImporterInfo {
  const pfx_importer_desc* desc = nullptr;
  const Plugin* plugin = nullptr;
};

// The descriptors a plugin handed over, copied into this host's struct layout at load (core.h's
// growth rule), so a plugin built against another minor version reads like one built with ours.
struct HostLayoutDescriptors;

// One loaded library. Owned by the registry; pointers stay valid until the registry dies.
struct Plugin {
  std::string path;
  std::string id, name, version;
  uint32_t abi_minor = 0;
  std::vector<const pfx_effect_desc*> effects;
  // The plugin's importers ("pfx.importers/1"); empty when it has none.
  std::vector<const pfx_importer_desc*> importers;
  // The plugin's CPU references ("pfx.references/1"), or null when it ships none.
  const pfx_reference_factory* references = nullptr;
  // For effects made from files at run time ("pfx.sources/1", ABI 1.5): the file and the name in
  // it of each (by effect id), and the files that gave no effect, each with its compiler's message
  // ("FILE:LINE:COLUMN: error: ..."). Empty for other plugins.
  struct EffectSource {
    std::string file, name;
  };
  std::map<std::string, EffectSource> effect_sources;
  std::vector<std::string> source_errors;
  // The sources factory's set_definitions (pfx/sources.h), for instances of the effects in
  // effect_sources; null when the plugin has none (Chain::set_source_definitions calls it).
  pfx_status (*set_definitions)(void* instance, const char* definitions) = nullptr;
  // The sources factory's params_at (pfx/sources.h); null when the plugin has none. Hosts call
  // params_at_frame_size, which copies its answer into this host's layout.
  const pfx_param_desc* (*params_at)(const char* effect_id, uint32_t width, uint32_t height) = nullptr;
  // The services this plugin was given (host_data points back at the registry's record).
  const pfx_host* host = nullptr;
  // The plugin's get_factory, for the factories this registry does not read itself (a Vulkan
  // host asks it for "pfx.vulkan_effects/1"): the caller checks the struct_size of what it gets.
  const void* (*get_factory)(const char* factory_id) = nullptr;
  // What effects, importers and references point into: this host's layout of the plugin's own
  // structs (arrays stepped by their struct_size, fields its version lacks zeroed).
  std::shared_ptr<const HostLayoutDescriptors> descriptors;
};

class PFX_HOST_API PluginRegistry {
 public:
  PluginRegistry(GlProcLoader gl_loader, LogSink log, std::string host_name = "libpfxhost");
  // Calls every plugin's deinit and unloads it. Destroy effect instances (the Chain) first.
  ~PluginRegistry();
  PluginRegistry(const PluginRegistry&) = delete;
  PluginRegistry& operator=(const PluginRegistry&) = delete;

  // Loads one library. On failure returns false, sets *error to "PATH: reason" and leaves the
  // registry as it was. While another live registry of the process holds the same library, loads
  // a private copy of the file instead, so this registry's plugin has globals, init and deinit of
  // its own (what it keeps of its host - this registry's thread pool and log - stays this
  // registry's); otherwise the file itself. plugins()'s path is the file's either way.
  bool load(const std::string& path, std::string* error);
  // Loads every *.so in a folder, in name order, but those already loaded from the same file;
  // returns the messages of those refused.
  std::vector<std::string> load_directory(const std::string& directory);
  // The files the loaded plugins that make effects from files could not use, each as its compiler
  // reports it ("FILE:LINE:COLUMN: error: ..."): no plugin was refused for them, they gave no effect.
  std::vector<std::string> source_errors() const;
  // The folders to search: the explicit ones, then each entry of PFX_PLUGIN_PATH (':'-separated).
  static std::vector<std::string> search_path(const std::vector<std::string>& explicit_directories);
  // load_directory over search_path(explicit_directories); a missing folder is an error message.
  std::vector<std::string> load_search_path(const std::vector<std::string>& explicit_directories);

  // Hot reload: loads the file of the loaded plugin `plugin_id` again, from a private copy under a
  // fresh name (dlopen would hand back the library already mapped for the same path). The new
  // version must keep the plugin id and pass every check load() makes. It then takes the old
  // version's place in plugins() and effects() and `adopt` is called, with the old version still
  // loaded: it must move everything made from the old version over to the new one (Chain::refresh
  // first, then ParamStore::add_effect, as reload_plugin in hot_reload.hpp does) and return true,
  // or return false with *reason to refuse the new version. Only then is the old version unloaded (deinit, dlclose).
  // Returns false, with *error "PATH: reason", when the new version is refused - by the loader or
  // by `adopt` - and the registry is then exactly as before: the old version keeps running.
  using AdoptFn = std::function<bool(std::string* reason)>;
  bool reload(const std::string& plugin_id, const AdoptFn& adopt, std::string* error);

  const std::vector<std::unique_ptr<Plugin>>& plugins() const { return plugins_; }
  const Plugin* find_plugin(const std::string& plugin_id) const;
  std::vector<EffectInfo> effects() const;  // in load order
  // Valid until the next load or reload; do not keep it across them.
  const EffectInfo* find_effect(const std::string& id) const;
  std::vector<ImporterInfo> importers() const;  // in load order
  const ImporterInfo* find_importer(const std::string& id) const;
  // The first importer (in load order) declaring the path's extension, compared case-insensitively
  // ("Model.OBJ" -> "obj"); null when none does.
  const ImporterInfo* find_importer_for_path(const std::string& path) const;

  // The thread pool offered to plugins as "pfx.thread_pool/1" (pfx/services.h): the registry's
  // own (sized to the machine's hardware threads, its threads started at the first parallel run
  // and joined when the registry dies), unless the host offers one of its own here. Applies to the
  // plugins loaded (or reloaded) afterwards, so call it before loading. nullptr: offer no pool, and
  // plugins run their work serially. The host's pool must outlive the registry.
  void set_thread_pool(const pfx_thread_pool* pool) { thread_pool_ = pool; }
  const pfx_thread_pool* thread_pool() const { return thread_pool_; }

  const LogSink& log() const { return log_; }
  const GlProcLoader& gl_loader() const { return gl_loader_; }

 // Internal: what the registry keeps per library (handle, entry, the pfx_host given to it).
  struct Record;

 private:
  // Whether a plugin of this registry was loaded from that file (paths compared resolved).
  bool loaded_from(const std::string& file) const;
  struct Opened;
  // Opens `file` (the plugin's own path, or a private copy of it) and checks it, reporting errors
  // against `path`. `replacing` is the plugin a reload replaces: its ids do not count as duplicates.
  bool open_plugin(const std::string& path, const std::string& file, const Plugin* replacing, Opened* out,
                   std::string* error);
  // Rebuilds effects() and importers() from plugins_.
  void rebuild_effect_index();

  GlProcLoader gl_loader_;
  LogSink log_;
  std::string host_name_;
  std::unique_ptr<ThreadPool> own_thread_pool_;  // joined after every plugin is unloaded
  const pfx_thread_pool* thread_pool_ = nullptr;
  std::vector<std::unique_ptr<Plugin>> plugins_;
  std::vector<std::unique_ptr<Record>> records_;  // parallel to plugins_
  std::vector<EffectInfo> effect_index_;
  std::vector<ImporterInfo> importer_index_;
};

// The parameters of `effect` as they are for a frame of width x height: its param_count
// descriptors in order, with the defaults and slider ranges of those flagged
// PFX_PARAM_FOLLOWS_FRAME_SIZE computed for that size (pfx/sources.h, params_at). Empty when the
// effect has none, its plugin cannot say, or the answer does not match the effect's parameters.
// Compiles on the plugin's side the first time a size is asked: call it when the size changes.
PFX_HOST_API std::vector<pfx_param_desc> params_at_frame_size(const EffectInfo& effect, uint32_t width, uint32_t height);

}  // namespace pfx::host
