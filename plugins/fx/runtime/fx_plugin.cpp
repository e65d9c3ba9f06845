// The FX plugin's entry point: an effect factory whose effects are the techniques of the ReShade
// FX files found at run time (fx_catalog.hpp). init stays cheap, as the ABI asks: the folders are
// read on the factory's first call.

#include <pfx/cpp/plugin_entry.hpp>
#include <pfx/pfx.h>

#include "fx_catalog.hpp"
#include "fx_effect.hpp"
#include "fx_instance.hpp"
#include "fx_vulkan_effect.hpp"
#include "codegen/spirv_module.hpp"

namespace pfx_fx {
namespace {

uint32_t effect_count() {
  try {
    return static_cast<uint32_t>(catalog().effects.size());  // at most kMaxEffects
  } catch (...) {
    return 0;
  }
}

const pfx_effect_desc* get_effect(uint32_t index) {
  try {
    return index < effect_count() ? &catalog().effects[index]->desc : nullptr;
  } catch (...) {
    return nullptr;
  }
}

const char* effect_file(const char* effect_id) {
  try {
    const FxEffectEntry* entry = find_effect(effect_id);
    return entry ? entry->file.c_str() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

const char* effect_source_name(const char* effect_id) {
  try {
    const FxEffectEntry* entry = find_effect(effect_id);
    return entry ? entry->technique.c_str() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

uint32_t error_count() {
  try {
    return static_cast<uint32_t>(catalog().errors.size());
  } catch (...) {
    return 0;
  }
}

const char* error(uint32_t index) {
  try {
    return index < catalog().errors.size() ? catalog().errors[index].message.c_str() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

pfx_status set_definitions(void* instance, const char* definitions) {
  FxInstance* fx = live_instance(instance);
  if (!fx || !definitions) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&] { return fx->set_definitions(definitions); });
}

const pfx_param_desc* params_at_size(const char* effect_id, uint32_t width, uint32_t height) {
  try {
    const FxEffectEntry* entry = find_effect(effect_id);
    const ParamTable* table = entry && width <= 16384 && height <= 16384
                                  ? params_at(*entry, static_cast<int>(width), static_cast<int>(height))
                                  : nullptr;
    return table ? table->descs.data() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

constexpr pfx_effect_factory kFactory = {sizeof(pfx_effect_factory), effect_count, get_effect};
constexpr pfx_source_factory kSources = {
    sizeof(pfx_source_factory), effect_file, effect_source_name, error_count, error, set_definitions, params_at_size};

constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.fx")
                             .name("pfx ReShade FX")
                             .version("0.1.0")
                             .effect_factory(&kFactory)
                             .sources(&kSources)
                             .factory(PFX_VULKAN_EFFECTS_FACTORY_ID, &kVulkanEffects)
                             .on_deinit(pfx::fx::release_spirv_compiler);

}  // namespace
}  // namespace pfx_fx

PFX_PLUGIN_ENTRY(pfx_fx::kPlugin)
