// Which effects the injected chain runs and with what values, from the settings and the preset
// file, the way pfx-render reads them: the preset gives the chain and values, --chain replaces its
// chain, --set overrides values; neither chain: every effect found, in the default order.
//
// The recipe is checked against the loaded effects' descriptors without any GL, so the launcher
// can refuse a bad chain, preset or assignment before the application starts, and the library
// (whose settings a user may have set by hand) can leave out only what is wrong and run the rest.
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
  // False when nobody chose the chain (no --chain, no chain in the preset): every effect found,
  // and the pipeline leaves out those that need inputs an application cannot give.
  bool chosen = false;
  std::string parameters_json;   // the preset's values, or empty
  std::vector<std::string> sets;  // assignments that apply, in order
};

// One thing of the settings that does not apply, and where it came from.
struct RecipeProblem {
  enum Source { CHAIN, PRESET, SET } source;
  std::string message;
};

// Reads the preset (when one is set) and checks the chain's effect ids, the preset's values and
// every assignment against the loaded effects. What does not apply is left out and described in
// *problems: an unknown effect leaves the chain (a chain left with none gives way to the default
// one), a preset that does not read or whose values do not apply is not used, an assignment that
// does not apply is dropped. *notes gets the store's remarks on values it adjusted (clamped).
ChainRecipe make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry,
                        std::vector<RecipeProblem>* problems, std::vector<std::string>* notes);
// Fills an empty chain and its store; false with *error naming the effect that failed to create.
bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error);
// Whether any effect of the chain is switched on: with none, the copy in and out is all there is.
bool any_enabled(const host::Chain& chain);
// Every loaded effect's values at the display-referred defaults, with as many instances of each as
// `effects` holds (at least one): the store an injected chain of those effects starts from.
host::ParamStore store_for(const std::vector<app::PresetEffect>& effects, const host::PluginRegistry& registry);
// "bloom, dof, glare": the loaded effects' ids, for messages.
std::string loaded_effect_ids(const host::PluginRegistry& registry);

}  // namespace pfx::inject
