#include "pfx/host/plugin_registry.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "descriptor_check.hpp"
#include "host_layout.hpp"
#include "own_library.hpp"

namespace fs = std::filesystem;

namespace pfx::host {

struct HostLayoutDescriptors {
  std::vector<std::unique_ptr<HostLayoutEffect>> effects;
  std::vector<std::unique_ptr<pfx_importer_desc>> importers;
  pfx_reference_factory references{};
};

// What the registry keeps per plugin besides the public Plugin: the library handle, the entry and
// the pfx_host handed to the plugin (its host_data points at this record).
struct PluginRegistry::Record {
  PluginRegistry* registry = nullptr;
  std::string plugin_id;
  void* library = nullptr;
  const pfx_entry* entry = nullptr;
  bool initialised = false;
  pfx_host host{};
  // The thread pool this plugin is offered, fixed when it is loaded (null: none).
  const pfx_thread_pool* thread_pool = nullptr;
};

namespace {

void host_log(void* host_data, pfx_log_level level, const char* message) {
  auto* record = static_cast<PluginRegistry::Record*>(host_data);
  if (record && record->registry && record->registry->log())
    record->registry->log()(level, record->plugin_id, message ? message : "(null message)");
}

pfx_gl_proc host_get_proc_address(void* host_data, const char* name) {
  auto* record = static_cast<PluginRegistry::Record*>(host_data);
  if (!record || !name || !record->registry->gl_loader()) return nullptr;
  return record->registry->gl_loader()(name);
}

// The services libpfxhost offers its plugins (pfx/services.h): the thread pool.
const void* host_get_service(void* host_data, const char* service_id) {
  auto* record = static_cast<PluginRegistry::Record*>(host_data);
  if (!record || !service_id) return nullptr;
  if (std::strcmp(service_id, PFX_SERVICE_THREAD_POOL) == 0) return record->thread_pool;
  return nullptr;
}

bool is_elf_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && std::memcmp(magic, "\x7f" "ELF", 4) == 0;
}

std::string text_or(const char* text, const char* fallback) { return text ? text : fallback; }

}  // namespace

// A plugin opened and checked but not yet part of the registry.
struct PluginRegistry::Opened {
  std::unique_ptr<Record> record;
  std::unique_ptr<Plugin> plugin;
};

namespace {

// Undoes a successful open: deinit, then dlclose. The record must hold no live instances.
void unload(PluginRegistry::Record& record) {
  if (record.initialised && record.entry->deinit) record.entry->deinit();
  record.initialised = false;
  close_own_library(record.registry, record.library);
  record.library = nullptr;
}

}  // namespace

PluginRegistry::PluginRegistry(GlProcLoader gl_loader, LogSink log, std::string host_name)
    : gl_loader_(std::move(gl_loader)),
      log_(std::move(log)),
      host_name_(std::move(host_name)),
      own_thread_pool_(std::make_unique<ThreadPool>()),
      thread_pool_(own_thread_pool_->service()) {
  if (!log_) log_ = [](pfx_log_level, const std::string&, const std::string&) {};
}

PluginRegistry::~PluginRegistry() {
  // Reverse load order, so a plugin loaded later (which may rely on nothing earlier, but might)
  // goes first.
  for (auto it = records_.rbegin(); it != records_.rend(); ++it) unload(**it);
}

namespace {

// Why `file` cannot be a plugin library before anything is loaded from it; empty when it may be.
std::string file_problem(const std::string& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return "no such file";
  if (!fs::is_regular_file(file, ec)) return "not a regular file";
  if (!is_elf_file(file)) return "not a shared library (no ELF header)";
  return "";
}

// Why the entry struct a library returned cannot be used; empty when it offers everything later
// steps rely on: its size, the ABI major, an id and the three functions.
std::string entry_problem(const pfx_entry* entry) {
  if (!entry) return PFX_ENTRY_SYMBOL "() returned NULL";
  if (entry->struct_size < PFX_ENTRY_MIN_SIZE)
    return "entry struct is " + std::to_string(entry->struct_size) + " bytes, expected at least " +
           std::to_string(PFX_ENTRY_MIN_SIZE) + " (ABI 1.0)";
  if (entry->abi_major != PFX_ABI_MAJOR)
    return "ABI major version mismatch: plugin built for ABI " + std::to_string(entry->abi_major) + "." +
           std::to_string(entry->abi_minor) + ", host implements ABI " + std::to_string(PFX_ABI_MAJOR) + "." +
           std::to_string(PFX_ABI_MINOR);
  if (!entry->id || !*entry->id) return "entry has no plugin id";
  if (!entry->init || !entry->deinit || !entry->get_factory) return "entry lacks init, deinit or get_factory";
  return "";
}

// Why the plugin id cannot join the registry: a reload that changes it, or another plugin's.
std::string plugin_id_problem(const PluginRegistry& registry, const pfx_entry& entry, const Plugin* replacing) {
  if (replacing && replacing->id != entry.id)
    return "the rebuilt library has plugin id '" + std::string(entry.id) + "', not '" + replacing->id + "'";
  for (const auto& plugin : registry.plugins())
    if (plugin.get() != replacing && plugin->id == entry.id)
      return "duplicate plugin id '" + plugin->id + "' (already loaded from " + plugin->path + ")";
  return "";
}

// The pfx_host the plugin is given: this registry's callbacks, with the record as their host_data.
void offer_host(PluginRegistry::Record* record, const pfx_entry* entry, const std::string& host_name) {
  record->plugin_id = entry->id;
  record->entry = entry;
  record->host.struct_size = sizeof(pfx_host);
  record->host.abi_major = PFX_ABI_MAJOR;
  record->host.abi_minor = PFX_ABI_MINOR;
  record->host.host_name = host_name.c_str();
  record->host.host_data = record;
  record->host.log = host_log;
  record->host.get_proc_address = host_get_proc_address;
  record->host.get_service = host_get_service;
}

// The public face of a plugin, from its entry; its effects, importers and references come later.
std::unique_ptr<Plugin> describe_plugin(const std::string& path, const pfx_entry& entry, const pfx_host* host) {
  auto plugin = std::make_unique<Plugin>();
  plugin->path = path;
  plugin->id = entry.id;
  plugin->name = text_or(entry.name, entry.id);
  plugin->version = text_or(entry.version, "");
  plugin->abi_minor = entry.abi_minor;
  plugin->host = host;
  plugin->get_factory = entry.get_factory;
  return plugin;
}

// Copies the plugin's effects into this host's layout, each checked and its id unique within the
// plugin and the registry (a reload's own old effects excepted). Returns why not, or empty. A
// plugin may provide no effects (an importer only): a NULL factory is fine.
std::string take_effects(const PluginRegistry& registry, const pfx_entry& entry, const Plugin* replacing,
                         Plugin* plugin, HostLayoutDescriptors* descriptors) {
  auto factory = static_cast<const pfx_effect_factory*>(entry.get_factory(PFX_EFFECTS_FACTORY_ID));
  if (!factory) return "";
  if (factory->struct_size < PFX_EFFECT_FACTORY_MIN_SIZE || !factory->effect_count || !factory->get_effect)
    return "effect factory is incomplete";
  std::set<std::string> own_ids;
  for (uint32_t i = 0, n = factory->effect_count(); i < n; ++i) {
    std::string problem;
    std::unique_ptr<HostLayoutEffect> effect = effect_in_host_layout(factory->get_effect(i), &problem);
    if (!effect) return "effect #" + std::to_string(i) + ": " + problem;
    const pfx_effect_desc* desc = &effect->desc;
    problem = check_effect_descriptor(desc);
    if (!problem.empty()) return "effect #" + std::to_string(i) + ": " + problem;
    if (!own_ids.insert(desc->id).second)
      return "duplicate effect id '" + std::string(desc->id) + "' within the plugin";
    const EffectInfo* other = registry.find_effect(desc->id);
    if (other && other->plugin != replacing)
      return "duplicate effect id '" + std::string(desc->id) + "' (already provided by plugin '" + other->plugin->id +
             "' from " + other->plugin->path + ")";
    plugin->effects.push_back(desc);
    descriptors->effects.push_back(std::move(effect));
  }
  return "";
}

// The same for the plugin's importers ("pfx.importers/1"), when it has a factory for them.
std::string take_importers(const PluginRegistry& registry, const pfx_entry& entry, const Plugin* replacing,
                           Plugin* plugin, HostLayoutDescriptors* descriptors) {
  auto factory = static_cast<const pfx_importer_factory*>(entry.get_factory(PFX_IMPORTERS_FACTORY_ID));
  if (!factory) return "";
  if (factory->struct_size < PFX_IMPORTER_FACTORY_MIN_SIZE || !factory->importer_count || !factory->get_importer)
    return "importer factory is incomplete";
  std::set<std::string> own_ids;
  for (uint32_t i = 0, n = factory->importer_count(); i < n; ++i) {
    const pfx_importer_desc* plugin_desc = factory->get_importer(i);
    std::string problem = check_importer_descriptor(plugin_desc);
    if (!problem.empty()) return "importer #" + std::to_string(i) + ": " + problem;
    descriptors->importers.push_back(std::make_unique<pfx_importer_desc>(read_sized(plugin_desc)));
    const pfx_importer_desc* desc = descriptors->importers.back().get();
    if (!own_ids.insert(desc->id).second)
      return "duplicate importer id '" + std::string(desc->id) + "' within the plugin";
    const ImporterInfo* other = registry.find_importer(desc->id);
    if (other && other->plugin != replacing)
      return "duplicate importer id '" + std::string(desc->id) + "' (already provided by plugin '" + other->plugin->id +
             "' from " + other->plugin->path + ")";
    plugin->importers.push_back(desc);
  }
  return "";
}

// The plugin's CPU references ("pfx.references/1"), kept only when they can be evaluated.
void take_references(const pfx_entry& entry, Plugin* plugin, HostLayoutDescriptors* descriptors) {
  auto references = static_cast<const pfx_reference_factory*>(entry.get_factory(PFX_REFERENCES_FACTORY_ID));
  if (!references || references->struct_size < PFX_REFERENCE_FACTORY_MIN_SIZE) return;
  descriptors->references = read_sized(references);
  if (descriptors->references.has_reference && descriptors->references.evaluate)
    plugin->references = &descriptors->references;
}

// Where the plugin's effects came from and which files gave none ("pfx.sources/1"), copied so
// they outlive a reload of the plugin, and how its instances take preprocessor definitions.
void take_sources(const pfx_entry& entry, Plugin* plugin) {
  auto sources = static_cast<const pfx_source_factory*>(entry.get_factory(PFX_SOURCES_FACTORY_ID));
  if (!sources || sources->struct_size < PFX_SOURCE_FACTORY_MIN_SIZE) return;
  if (sources->effect_file && sources->effect_source_name)
    for (const pfx_effect_desc* effect : plugin->effects) {
      const char* file = sources->effect_file(effect->id);
      const char* name = sources->effect_source_name(effect->id);
      if (file) plugin->effect_sources[effect->id] = {file, name ? name : ""};
    }
  if (sources->error_count && sources->error)
    for (uint32_t i = 0, n = sources->error_count(); i < n; ++i)
      if (const char* message = sources->error(i)) plugin->source_errors.push_back(message);
  if (PFX_STRUCT_HAS(sources, pfx_source_factory, set_definitions)) plugin->set_definitions = sources->set_definitions;
  if (PFX_STRUCT_HAS(sources, pfx_source_factory, params_at)) plugin->params_at = sources->params_at;
}

}  // namespace

bool PluginRegistry::open_plugin(const std::string& path, const std::string& file, const Plugin* replacing, Opened* out,
                                 std::string* error) {
  auto fail = [&](const std::string& reason) {
    if (error) *error = path + ": " + reason;
    return false;
  };
  std::string reason = file_problem(file);
  if (!reason.empty()) return fail(reason);

  auto record = std::make_unique<Record>();
  record->registry = this;
  record->thread_pool = thread_pool_;
  // This registry's own library: another registry of the process holding the same one makes it a
  // private copy, so the plugin's globals (what init is told of its host) are this host's alone.
  void* library = open_own_library(this, file, path, &reason);
  if (!library) return fail("cannot be loaded: " + reason);
  struct Closer {
    const PluginRegistry* owner;
    void*& library;
    ~Closer() { close_own_library(owner, library); }
  } closer{this, library};

  dlerror();
  auto get_entry = reinterpret_cast<pfx_get_entry_fn>(dlsym(library, PFX_ENTRY_SYMBOL));
  if (!get_entry) return fail("no entry symbol " PFX_ENTRY_SYMBOL " (not a pfx plugin)");
  const pfx_entry* entry = get_entry();
  reason = entry_problem(entry);
  if (reason.empty()) reason = plugin_id_problem(*this, *entry, replacing);
  if (!reason.empty()) return fail(reason);

  offer_host(record.get(), entry, host_name_);
  pfx_status status = entry->init(&record->host);
  if (status != PFX_OK) return fail("init failed (status " + std::to_string(status) + ")");
  record->initialised = true;

  std::unique_ptr<Plugin> plugin = describe_plugin(path, *entry, &record->host);
  auto descriptors = std::make_shared<HostLayoutDescriptors>();
  reason = take_effects(*this, *entry, replacing, plugin.get(), descriptors.get());
  if (reason.empty()) reason = take_importers(*this, *entry, replacing, plugin.get(), descriptors.get());
  if (!reason.empty()) {
    entry->deinit();
    return fail(reason);
  }
  take_references(*entry, plugin.get(), descriptors.get());
  take_sources(*entry, plugin.get());
  plugin->descriptors = std::move(descriptors);

  record->library = library;
  library = nullptr;  // the record owns it now
  out->record = std::move(record);
  out->plugin = std::move(plugin);
  return true;
}

bool PluginRegistry::load(const std::string& path, std::string* error) {
  Opened opened;
  if (!open_plugin(path, path, nullptr, &opened, error)) return false;
  log_(PFX_LOG_DEBUG, "host", "loaded " + opened.plugin->id + " " + opened.plugin->version + " from " + path);
  plugins_.push_back(std::move(opened.plugin));
  records_.push_back(std::move(opened.record));
  rebuild_effect_index();
  return true;
}

bool PluginRegistry::reload(const std::string& plugin_id, const AdoptFn& adopt, std::string* error) {
  auto at = std::find_if(plugins_.begin(), plugins_.end(), [&](const auto& p) { return p->id == plugin_id; });
  if (at == plugins_.end()) {
    if (error) *error = "no plugin '" + plugin_id + "' is loaded";
    return false;
  }
  const size_t index = static_cast<size_t>(at - plugins_.begin());
  const std::string path = plugins_[index]->path;
  std::string copy, reason;
  if (!make_private_copy(path, &copy, &reason)) {
    if (error) *error = path + ": cannot make a private copy to reload from: " + reason;
    return false;
  }
  Opened opened;
  bool ok = open_plugin(path, copy, plugins_[index].get(), &opened, error);
  // The mapping keeps the library alive; the copy's name is not needed any more.
  std::error_code ec;
  fs::remove(copy, ec);
  if (!ok) return false;

  std::swap(plugins_[index], opened.plugin);
  std::swap(records_[index], opened.record);
  rebuild_effect_index();
  // `opened` now holds the old version, still loaded, so adopt can destroy what was made from it.
  if (adopt && !adopt(&reason)) {
    std::swap(plugins_[index], opened.plugin);
    std::swap(records_[index], opened.record);
    rebuild_effect_index();
    unload(*opened.record);
    if (error) *error = path + ": " + reason;
    return false;
  }
  unload(*opened.record);
  log_(PFX_LOG_DEBUG, "host", "reloaded " + plugin_id + " " + plugins_[index]->version + " from " + path);
  return true;
}

void PluginRegistry::rebuild_effect_index() {
  effect_index_.clear();
  importer_index_.clear();
  for (const auto& plugin : plugins_) {
    for (const pfx_effect_desc* desc : plugin->effects) effect_index_.push_back({desc, plugin.get()});
    for (const pfx_importer_desc* desc : plugin->importers) importer_index_.push_back({desc, plugin.get()});
  }
}

std::vector<std::string> PluginRegistry::load_directory(const std::string& directory) {
  std::vector<std::string> errors;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) {
    errors.push_back(directory + ": no such plugin directory");
    return errors;
  }
  std::vector<std::string> files;
  for (const auto& item : fs::directory_iterator(directory, ec))
    if (item.path().extension() == ".so") files.push_back(item.path().string());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    // A folder named twice (given, and in PFX_PLUGIN_PATH too) is the same plugins, not duplicates.
    if (loaded_from(file)) continue;
    std::string error;
    if (!load(file, &error)) errors.push_back(error);
  }
  return errors;
}

bool PluginRegistry::loaded_from(const std::string& file) const {
  std::error_code ec;
  const fs::path wanted = fs::weakly_canonical(file, ec);
  for (const auto& plugin : plugins_)
    if (fs::weakly_canonical(plugin->path, ec) == wanted) return true;
  return false;
}

std::vector<std::string> PluginRegistry::source_errors() const {
  std::vector<std::string> messages;
  for (const auto& plugin : plugins_) messages.insert(messages.end(), plugin->source_errors.begin(), plugin->source_errors.end());
  return messages;
}

std::vector<std::string> PluginRegistry::search_path(const std::vector<std::string>& explicit_directories) {
  std::vector<std::string> directories = explicit_directories;
  if (const char* env = std::getenv("PFX_PLUGIN_PATH")) {
    std::string list = env;
    size_t start = 0;
    while (start <= list.size()) {
      size_t end = list.find(':', start);
      if (end == std::string::npos) end = list.size();
      if (end > start) directories.push_back(list.substr(start, end - start));
      start = end + 1;
    }
  }
  return directories;
}

std::vector<std::string> PluginRegistry::load_search_path(const std::vector<std::string>& explicit_directories) {
  std::vector<std::string> errors;
  for (const auto& directory : search_path(explicit_directories)) {
    auto more = load_directory(directory);
    errors.insert(errors.end(), more.begin(), more.end());
  }
  return errors;
}

std::vector<EffectInfo> PluginRegistry::effects() const { return effect_index_; }

const Plugin* PluginRegistry::find_plugin(const std::string& plugin_id) const {
  for (const auto& plugin : plugins_)
    if (plugin->id == plugin_id) return plugin.get();
  return nullptr;
}

const EffectInfo* PluginRegistry::find_effect(const std::string& id) const {
  for (const auto& info : effect_index_)
    if (id == info.desc->id) return &info;
  return nullptr;
}

std::vector<ImporterInfo> PluginRegistry::importers() const { return importer_index_; }

const ImporterInfo* PluginRegistry::find_importer(const std::string& id) const {
  for (const auto& info : importer_index_)
    if (id == info.desc->id) return &info;
  return nullptr;
}

const ImporterInfo* PluginRegistry::find_importer_for_path(const std::string& path) const {
  std::string extension = fs::path(path).extension().string();
  if (extension.size() < 2) return nullptr;
  extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const auto& info : importer_index_)
    for (uint32_t i = 0; i < info.desc->extension_count; ++i)
      if (extension == info.desc->extensions[i]) return &info;
  return nullptr;
}

std::vector<pfx_param_desc> params_at_frame_size(const EffectInfo& effect, uint32_t width, uint32_t height) {
  if (!effect.desc || !effect.plugin || !effect.plugin->params_at || effect.desc->param_count == 0) return {};
  const pfx_param_desc* table = effect.plugin->params_at(effect.desc->id, width, height);
  if (!table) return {};
  std::string problem;
  std::vector<pfx_param_desc> params =
      read_sized_array(table, effect.desc->param_count, PFX_PARAM_DESC_MIN_SIZE, "parameter", &problem);
  // The same parameters as the effect's own, or none: a host matches them by position.
  for (uint32_t i = 0; i < params.size(); ++i) {
    const pfx_param_desc& listed = effect.desc->params[i];
    if (!params[i].id || std::strcmp(params[i].id, listed.id) != 0 || params[i].type != listed.type ||
        !check_param_descriptor(params[i]).empty())
      return {};
    params[i].struct_size = sizeof(pfx_param_desc);
  }
  return problem.empty() ? params : std::vector<pfx_param_desc>{};
}

}  // namespace pfx::host
