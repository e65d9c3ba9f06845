#include "fx_definitions.hpp"

#include <algorithm>

namespace pfx_fx {

std::vector<std::string> remove_own_definitions(const Definitions& own, Definitions* definitions) {
  std::vector<std::string> removed;
  Definitions kept;
  for (const auto& definition : *definitions) {
    const bool is_own = std::any_of(own.begin(), own.end(), [&](const auto& o) { return o.first == definition.first; });
    if (!is_own)
      kept.push_back(definition);
    else if (std::find(removed.begin(), removed.end(), definition.first) == removed.end())
      removed.push_back(definition.first);
  }
  *definitions = std::move(kept);
  return removed;
}

}  // namespace pfx_fx
