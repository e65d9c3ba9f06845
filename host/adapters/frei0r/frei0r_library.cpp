#include "frei0r_library.hpp"

#include <cstdio>
#include <filesystem>
#include <mutex>

#include "frei0r_api.hpp"

#include "adapter_plugins.hpp"
#include "headless_context.hpp"

namespace pfx::frei0r {
namespace {

std::mutex library_mutex;
// Destroyed when the host unloads the library (or the process ends): the plugins unload then.
std::shared_ptr<Library> current;

const char* kChainName = "pfx_chain";

// Plugin messages go to stderr, named after this library, above the chatter of INFO: inside
// somebody else's program only what a user must act on is said.
host::LogSink library_log(const std::string& name) {
  return [name](pfx_log_level level, const std::string& source, const std::string& message) {
    if (level < PFX_LOG_WARNING) return;
    std::fprintf(stderr, "%s: %s: [%s] %s\n", name.c_str(), host::log_level_name(level), source.c_str(),
                 message.c_str());
  };
}

std::shared_ptr<Library> make_library() {
  auto self = std::make_shared<Library>();
  self->file = adapters::library_path_of(reinterpret_cast<const void*>(&make_library));
  std::string stem = std::filesystem::path(self->file).stem().string();
  self->name = stem.empty() ? kChainName : stem;
  self->kind = self->name.rfind("pfx_", 0) == 0 && self->name != kChainName ? Library::Kind::EFFECT
                                                                            : Library::Kind::CHAIN;
  if (self->kind == Library::Kind::EFFECT) self->effect_id = self->name.substr(4);
  self->registry = std::make_unique<host::PluginRegistry>(
      [](const char* name) { return app::HeadlessContext::get_proc_address(nullptr, name); },
      library_log(self->name), self->name + " (pfx frei0r)");
  self->problems = adapters::load_adapter_plugins(
      *self->registry, {self->file, {PFX_FREI0R_TO_PLUGINS, "../../plugins"}});
  if (self->kind == Library::Kind::CHAIN) {
    self->explanation =
        "A chain of pfx effects (docs/hosts.md): chain = effect ids in order (none: no effect), set = "
        "effect.param=value items separated by ';', transfer = srgb or linear, preset = a pfx-view (.json) or ReShade (.ini) preset";
    self->params = {
        {"chain", F0R_PARAM_STRING, "Effects in order, separated by ','; none: no effect; empty (the default): the preset's chain, else bloom"},
        {"set", F0R_PARAM_STRING, "effect.param=value items separated by ';' (bloom#2.x for a second bloom)"},
        {"transfer", F0R_PARAM_STRING, "How the frame's values relate to light: srgb (default) or linear"},
        {"preset", F0R_PARAM_STRING, "A preset file (pfx-view's .json, ReShade's .ini): chain, on/off, values; what is not there is left out with one warning"}};
    return self;
  }
  if (const host::EffectInfo* info = self->registry->find_effect(self->effect_id)) {
    self->effect = info->desc;
    self->params = effect_slots(*info->desc);
    self->explanation = std::string(info->desc->label ? info->desc->label : info->desc->id) + " (pfx): " +
                        (info->desc->description ? info->desc->description : "");
  } else {
    self->problems.push_back("the pfx effect '" + self->effect_id + "' is not among the plugins loaded");
    self->explanation = "pfx effect '" + self->effect_id + "' (not found: frames pass through)";
  }
  return self;
}

}  // namespace

Library::~Library() = default;

std::shared_ptr<Library> library() {
  std::lock_guard<std::mutex> lock(library_mutex);
  if (!current) current = make_library();
  return current;
}

}  // namespace pfx::frei0r
