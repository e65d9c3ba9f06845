#include "panel_names.hpp"

#include <map>

namespace pfx::app {

std::vector<std::string> panel_names(const std::vector<std::string>& chain_effect_ids) {
  std::map<std::string, size_t> total, seen;
  for (const auto& id : chain_effect_ids) ++total[id];
  std::vector<std::string> names;
  for (const auto& id : chain_effect_ids) {
    const size_t number = ++seen[id];
    names.push_back(total[id] > 1 ? id + "#" + std::to_string(number) : id);
  }
  return names;
}

}  // namespace pfx::app
