#include "default_chain.hpp"

#include <algorithm>

namespace pfx::app {

std::vector<std::string> default_chain(const pfx::host::PluginRegistry& registry) {
  const std::vector<std::string> preferred = {"tiledlights", "dof", "bloom", "glare"};
  std::vector<std::string> chain;
  for (const auto& id : preferred)
    if (registry.find_effect(id)) chain.push_back(id);
  for (const auto& effect : registry.effects())
    if (std::find(chain.begin(), chain.end(), effect.desc->id) == chain.end()) chain.push_back(effect.desc->id);
  return chain;
}

}  // namespace pfx::app
