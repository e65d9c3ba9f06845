// The names the viewer's panels give the instances of a chain: the store's names ("bloom",
// "bloom#2"), but "bloom#1" rather than "bloom" once the chain holds a second bloom, so the two
// panels read bloom#1 and bloom#2. Every name shown is one --set and presets accept.
#pragma once

#include <string>
#include <vector>

namespace pfx::app {

// One name per entry of the chain's effect ids, in chain order (disabled instances count).
std::vector<std::string> panel_names(const std::vector<std::string>& chain_effect_ids);

}  // namespace pfx::app
