// The chain our programs run when none is given: every loaded effect, in the order that makes
// sense for post effects.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::app {

// Lighting makes the colour, depth of field works on scene-referred colour, bloom and glare
// spread what is left; anything else runs after them in load order.
std::vector<std::string> default_chain(const pfx::host::PluginRegistry& registry);

}  // namespace pfx::app
