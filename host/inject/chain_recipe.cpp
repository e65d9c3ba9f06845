#include "chain_recipe.hpp"

#include "default_chain.hpp"

namespace pfx::inject {

bool make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry, ChainRecipe* out,
                 std::string* error) {
  ChainRecipe recipe;
  app::Preset preset;
  if (!settings.preset.empty() && !app::read_preset(settings.preset, &preset, error)) return false;
  if (settings.chain) {
    for (const auto& id : *settings.chain) recipe.effects.push_back({id, true});
  } else if (preset.chain) {
    recipe.effects = *preset.chain;
  } else {
    for (const auto& id : app::default_chain(registry)) recipe.effects.push_back({id, true});
  }
  recipe.parameters_json = preset.parameters_json;
  recipe.sets = settings.sets;
  *out = std::move(recipe);
  return true;
}

bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes) {
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
      *error = "--set " + *error;
      return false;
    }
    if (!note.empty()) notes->push_back("--set " + assignment + ": " + note);
  }
  return true;
}

bool any_enabled(const host::Chain& chain) {
  for (size_t i = 0; i < chain.size(); ++i)
    if (chain.enabled(i)) return true;
  return false;
}

}  // namespace pfx::inject
