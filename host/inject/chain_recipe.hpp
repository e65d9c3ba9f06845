// Which effects the injected chain runs and with what values, from the settings and the preset
// file, the way pfx-render reads them: the preset gives the chain and values, --chain replaces its
// chain, --set overrides values; neither chain: every effect found, in the default order.
#pragma once

#include <string>

#include <pfx/host/plugin_registry.hpp>

#include "chain_builder.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

using app::any_enabled;
using app::build_chain;
using app::ChainRecipe;

// Reads the preset (when one is set); false with *error naming the file and the problem.
bool make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry, ChainRecipe* out,
                 std::string* error);

}  // namespace pfx::inject
