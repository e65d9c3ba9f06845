#include "chain_builder.hpp"

#include "default_chain.hpp"

namespace pfx::app {

bool make_chain_recipe(const std::string& preset_path, const std::optional<std::vector<std::string>>& chain,
                       const std::vector<std::string>& sets, const host::PluginRegistry& registry, WithoutChain without,
                       ChainRecipe* out, std::string* error) {
  ChainRecipe recipe;
  Preset preset;
  if (!preset_path.empty() && !read_preset(preset_path, &preset, error)) return false;
  if (chain) {
    for (const auto& id : *chain) recipe.effects.push_back({id, true});
  } else if (preset.chain) {
    recipe.effects = *preset.chain;
  } else if (without == WithoutChain::DEFAULT_CHAIN) {
    for (const auto& id : default_chain(registry)) recipe.effects.push_back({id, true});
  }
  recipe.parameters_json = preset.parameters_json;
  recipe.sets = sets;
  *out = std::move(recipe);
  return true;
}

bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes, const std::string& set_origin) {
  for (const auto& effect : recipe.effects) {
    if (!chain->add(effect.id, error)) return false;
    chain->set_enabled(chain->size() - 1, effect.enabled);
  }
  // Values after the chain: "bloom#2" exists once the chain holds a second bloom.
  if (!recipe.parameters_json.empty() && !params->from_json(recipe.parameters_json, error)) {
    *error = "preset parameters: " + *error;
    return false;
  }
  for (const auto& assignment : recipe.sets) {
    std::string note;
    if (!params->set_assignment(assignment, error, &note)) {
      *error = set_origin + " " + *error;
      return false;
    }
    if (!note.empty()) notes->push_back(set_origin + " " + assignment + ": " + note);
  }
  return true;
}

bool any_enabled(const host::Chain& chain) {
  for (size_t i = 0; i < chain.size(); ++i)
    if (chain.enabled(i)) return true;
  return false;
}

}  // namespace pfx::app
