// Which effects a host runs and with what values, read the way every pfx host reads them: a
// preset gives the chain and values, an explicit chain replaces the preset's, assignments
// ("effect.param=value") override values. Shared by pfx-inject and the video-host adapters.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "preset.hpp"

namespace pfx::app {

struct ChainRecipe {
  std::vector<PresetEffect> effects;
  std::string parameters_json;  // the preset's values, or empty
  std::vector<std::string> sets;
};

// What runs when neither the chain nor the preset names effects.
enum class WithoutChain {
  DEFAULT_CHAIN,  // every effect found, in the default order (default_chain.hpp)
  NO_EFFECT       // nothing: the frame passes through
};

// Reads the preset (when preset_path is not empty); false with *error naming the file and the
// problem. `chain` unset: the preset's chain, else as `without` says.
bool make_chain_recipe(const std::string& preset_path, const std::optional<std::vector<std::string>>& chain,
                       const std::vector<std::string>& sets, const host::PluginRegistry& registry, WithoutChain without,
                       ChainRecipe* out, std::string* error);
// Fills an empty chain and its store; false with *error naming the effect or assignment (an
// assignment's error starts with `set_origin`, the option that gave it). *notes gets the store's
// remarks on assignments it adjusted (a value clamped to its range).
bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes, const std::string& set_origin = "--set");
// Whether any effect of the chain is switched on: with none, the copy in and out is all there is.
bool any_enabled(const host::Chain& chain);

}  // namespace pfx::app
