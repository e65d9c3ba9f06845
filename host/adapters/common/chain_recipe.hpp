// Which effects the injected chain runs and with what values, from the settings and the preset
// file, the way every host of 8-bit frames reads them (chain_builder.hpp): the preset gives the
// chain and values, --chain replaces its chain, --set overrides values; neither chain: every
// effect found, in the default order.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_builder.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

using app::any_enabled;
using app::build_chain;
using app::ChainRecipe;
using app::loaded_effect_ids;
using app::RecipeProblem;
using app::store_for;

// make_chain_recipe over the injector's settings: what does not apply is left out and described
// in *problems (the launcher refuses it, the library names it and runs the rest).
ChainRecipe make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry,
                        std::vector<RecipeProblem>* problems, std::vector<std::string>* notes);

}  // namespace pfx::inject
