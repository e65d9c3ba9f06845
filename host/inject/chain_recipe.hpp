// Which effects the injected chain runs and with what values, from the settings and the preset
// file, the way pfx-render reads them: the preset gives the chain and values, --chain replaces its
// chain, --set overrides values; neither chain: every effect found, in the default order.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "inject_settings.hpp"
#include "preset.hpp"

namespace pfx::inject {

struct ChainRecipe {
  std::vector<app::PresetEffect> effects;
  std::string parameters_json;  // the preset's values, or empty
  std::vector<std::string> sets;
};

// Reads the preset (when one is set); false with *error naming the file and the problem.
bool make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry, ChainRecipe* out,
                 std::string* error);
// Fills an empty chain and its store; false with *error naming the effect or assignment.
// *notes gets the store's remarks on assignments it adjusted (a value clamped to its range).
bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes);
// Whether any effect of the chain is switched on: with none, the copy in and out is all there is.
bool any_enabled(const host::Chain& chain);

}  // namespace pfx::inject
