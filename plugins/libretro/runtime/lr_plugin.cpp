// The libretro plugin's entry point: an effect factory whose effects are the shader presets found
// at run time (lr_catalog.hpp), and a sources factory saying which file each came from and which
// presets could not be read. init stays cheap, as the ABI asks: the folders are read on the
// factory's first call.

#include <pfx/cpp/plugin_entry.hpp>
#include <pfx/pfx.h>

#include "lr_catalog.hpp"
#include "slang_spirv.hpp"

namespace pfx_libretro {
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
    const LrEffectEntry* entry = find_effect(effect_id);
    return entry ? entry->file.c_str() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

const char* effect_source_name(const char* effect_id) {
  try {
    const LrEffectEntry* entry = find_effect(effect_id);
    return entry ? entry->label.c_str() : nullptr;
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

constexpr pfx_effect_factory kFactory = {sizeof(pfx_effect_factory), effect_count, get_effect};
// No preprocessor definitions and no parameters that follow the frame size: both are left empty.
constexpr pfx_source_factory kSources = {
    sizeof(pfx_source_factory), effect_file, effect_source_name, error_count, error, nullptr, nullptr};

constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.libretro")
                             .name("pfx libretro shader presets")
                             .version("0.1.0")
                             .effect_factory(&kFactory)
                             .sources(&kSources)
                             .on_deinit(pfx::libretro::release_slang_compiler);

}  // namespace
}  // namespace pfx_libretro

PFX_PLUGIN_ENTRY(pfx_libretro::kPlugin)
