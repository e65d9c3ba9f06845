#include "plugin_checks.hpp"

#include <dlfcn.h>

#include <cstring>
#include <set>

#include <pfx/pfx.h>

#include "descriptor_checks.hpp"
#include "validator_host.hpp"

namespace pfx::validate {
namespace {

// Loads the library and finds its entry; reports the problem and returns null when it cannot.
const pfx_entry* open_entry(const std::string& path, CheckReporter& report) {
  report.step("dlopen(RTLD_NOW | RTLD_LOCAL)");
  void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = dlerror();
    report.problem(std::string("cannot be loaded: ") + (why ? why : "unknown dlopen error"));
    return nullptr;
  }
  // Never dlclosed: the child process ends right after the check.
  auto get_entry = reinterpret_cast<pfx_get_entry_fn>(dlsym(library, PFX_ENTRY_SYMBOL));
  if (!get_entry) {
    report.problem("no entry symbol " PFX_ENTRY_SYMBOL " (not a pfx plugin)");
    return nullptr;
  }
  report.step(PFX_ENTRY_SYMBOL "()");
  const pfx_entry* entry = get_entry();
  if (!entry) report.problem(PFX_ENTRY_SYMBOL "() returned NULL");
  return entry;
}

// The entry if it is usable for calling init: the entry check says what is wrong otherwise.
const pfx_entry* usable_entry(const std::string& path, CheckReporter& report) {
  const pfx_entry* entry = open_entry(path, report);
  if (!entry) return nullptr;
  if (entry->struct_size < PFX_ENTRY_MIN_SIZE || entry->abi_major != PFX_ABI_MAJOR || !entry->init || !entry->deinit ||
      !entry->get_factory) {
    report.problem("the entry struct is unusable (see the entry check)");
    return nullptr;
  }
  return entry;
}

bool init_ok(const pfx_entry* entry, ValidatorHost& host, CheckReporter& report, const char* when) {
  const std::string call = *when ? std::string("init ") + when : std::string("init");
  report.step(call);
  const pfx_status status = entry->init(host.host());
  if (status != PFX_OK) report.problem(call + " returned status " + std::to_string(status) + host.errors_logged());
  return status == PFX_OK;
}

}  // namespace

void check_load(const std::string& path, CheckReporter& report) { open_entry(path, report); }

void check_entry(const std::string& path, CheckReporter& report) {
  const pfx_entry* entry = open_entry(path, report);
  if (!entry) return;
  if (entry->struct_size < PFX_ENTRY_MIN_SIZE) {
    report.problem("struct_size " + std::to_string(entry->struct_size) + " is smaller than pfx_entry's first version (" +
                   std::to_string(PFX_ENTRY_MIN_SIZE) + ")");
    return;  // the fields after struct_size may not exist
  }
  if (entry->abi_major != PFX_ABI_MAJOR)
    report.problem("ABI major " + std::to_string(entry->abi_major) + ", this host implements " +
                   std::to_string(PFX_ABI_MAJOR));
  if (!is_plugin_id(entry->id))
    report.problem("plugin id '" + std::string(entry->id ? entry->id : "(null)") +
                   "' is not reverse-DNS (two or more dot-separated parts of [a-z0-9_-])");
  else
    report.fact("plugin_id", entry->id);
  if (!entry->name || !*entry->name) report.problem("no name");
  else report.fact("name", entry->name);
  if (!entry->version || !*entry->version) report.problem("no version");
  else report.fact("version", entry->version);
  if (!entry->init) report.problem("init is NULL");
  if (!entry->deinit) report.problem("deinit is NULL");
  if (!entry->get_factory) report.problem("get_factory is NULL");
}

void check_init_deinit(const std::string& path, CheckReporter& report) {
  const pfx_entry* entry = usable_entry(path, report);
  if (!entry) return;
  ValidatorHost host;
  if (!init_ok(entry, host, report, "(first call)")) return;
  if (!init_ok(entry, host, report, "(second call: init must be idempotent)")) return;
  report.step("deinit");
  entry->deinit();
  if (!init_ok(entry, host, report, "(after deinit)")) return;
  report.step("deinit (second time)");
  entry->deinit();
  if (host.gl_requests() > 0)
    report.problem("asked for " + std::to_string(host.gl_requests()) + " GL function(s) (first: " + host.first_gl_request() +
                   ") in init or deinit, where no context is current");
}

void check_factories(const std::string& path, CheckReporter& report) {
  const pfx_entry* entry = usable_entry(path, report);
  if (!entry) return;
  ValidatorHost host;
  if (!init_ok(entry, host, report, "")) return;
  for (const char* unknown : {"pfx.validate.no-such-factory/1", "pfx.effects/999", ""}) {
    report.step(std::string("get_factory(\"") + unknown + "\")");
    if (entry->get_factory(unknown))
      report.problem(std::string("get_factory(\"") + unknown + "\") returned a factory; unknown ids must give NULL");
  }
  report.step("get_factory(\"" PFX_EFFECTS_FACTORY_ID "\")");
  auto factory = static_cast<const pfx_effect_factory*>(entry->get_factory(PFX_EFFECTS_FACTORY_ID));
  if (!factory) {
    report.step("get_factory(\"" PFX_IMPORTERS_FACTORY_ID "\")");
    if (!entry->get_factory(PFX_IMPORTERS_FACTORY_ID))
      report.problem("neither an effect factory nor an importer factory: the plugin provides nothing");
    entry->deinit();
    return;
  }
  if (factory->struct_size < PFX_EFFECT_FACTORY_MIN_SIZE || !factory->effect_count || !factory->get_effect) {
    report.problem("the effect factory is incomplete (struct_size, effect_count or get_effect)");
    return;
  }
  report.step("effect_count()");
  const uint32_t count = factory->effect_count();
  // A plugin that makes its effects from files it finds ("pfx.sources/1", the FX plugin) may find
  // none; any other effect factory without effects is a mistake.
  if (count == 0 && !entry->get_factory(PFX_SOURCES_FACTORY_ID)) report.problem("the effect factory has no effects");
  std::set<std::string> ids;
  for (uint32_t i = 0; i < count && i < 10000; ++i) {
    report.step("get_effect(" + std::to_string(i) + ")");
    const pfx_effect_desc* desc = factory->get_effect(i);
    if (!desc) {
      report.problem("get_effect(" + std::to_string(i) + ") returned NULL (effect_count is " + std::to_string(count) + ")");
      continue;
    }
    report.step("reading the id of effect #" + std::to_string(i));
    if (!is_effect_or_param_id(desc->id)) {
      report.problem("effect #" + std::to_string(i) + ": id '" + std::string(desc->id ? desc->id : "(null)") +
                     "' is not [a-z0-9_]+");
      continue;
    }
    if (!ids.insert(desc->id).second) {
      report.problem("effect id '" + std::string(desc->id) + "' repeats");
      continue;
    }
    report.fact("effect", desc->id);
  }
  report.step("deinit");
  entry->deinit();
}

void check_descriptors(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  const pfx_entry* entry = usable_entry(path, report);
  if (!entry) return;
  ValidatorHost host;
  if (!init_ok(entry, host, report, "")) return;
  auto factory = static_cast<const pfx_effect_factory*>(entry->get_factory(PFX_EFFECTS_FACTORY_ID));
  for (uint32_t i = 0; factory && i < factory->effect_count(); ++i) {
    const pfx_effect_desc* desc = factory->get_effect(i);
    if (!desc || !desc->id || effect_id != desc->id) continue;
    report.step("reading the descriptor of '" + effect_id + "'");
    for (const std::string& problem : effect_descriptor_problems(*desc)) report.problem(problem);
    entry->deinit();
    return;
  }
  report.problem("effect '" + effect_id + "' is no longer listed by the factory");
}

}  // namespace pfx::validate
