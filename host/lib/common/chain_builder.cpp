#include "chain_builder.hpp"

#include <algorithm>
#include <map>

#include "default_chain.hpp"

namespace pfx::app {
namespace {

// The effects of `wanted` that are loaded; each other one is a problem from `source`.
std::vector<PresetEffect> loaded_only(const std::vector<PresetEffect>& wanted, const host::PluginRegistry& registry,
                                      RecipeProblem::Source source, std::vector<RecipeProblem>* problems) {
  std::vector<PresetEffect> kept;
  for (const auto& effect : wanted) {
    if (registry.find_effect(effect.id)) kept.push_back(effect);
    else
      problems->push_back({source, "effect '" + effect.id + "' is not loaded (loaded: " + loaded_effect_ids(registry) + ")"});
  }
  return kept;
}

}  // namespace

host::ParamStore store_for(const std::vector<PresetEffect>& effects, const host::PluginRegistry& registry) {
  host::ParamStore store(host::DefaultSet::DISPLAY_REFERRED);
  std::map<std::string, size_t> instances;
  for (const auto& effect : effects) ++instances[effect.id];
  for (const auto& effect : registry.effects()) {
    store.add_effect(effect.desc);
    store.set_instance_count(effect.desc->id, std::max<size_t>(1, instances[effect.desc->id]));
  }
  return store;
}

std::string loaded_effect_ids(const host::PluginRegistry& registry) {
  std::string ids;
  for (const auto& effect : registry.effects()) ids += (ids.empty() ? "" : ", ") + std::string(effect.desc->id);
  return ids.empty() ? "none" : ids;
}

ChainRecipe make_chain_recipe(const std::string& preset_path, const std::optional<std::vector<std::string>>& chain,
                              const std::vector<std::string>& sets, const host::PluginRegistry& registry,
                              WithoutChain without, std::vector<RecipeProblem>* problems,
                              std::vector<std::string>* notes) {
  ChainRecipe recipe;
  Preset preset;
  std::string error;
  if (!preset_path.empty() && !read_preset(preset_path, &preset, &error)) {
    problems->push_back({RecipeProblem::PRESET, error});
    preset = Preset{};
  }
  // The first chain that names something usable: the given one, then the preset's. An empty
  // given chain ("none") is a choice too: no effect.
  if (chain) {
    std::vector<PresetEffect> wanted;
    for (const auto& id : *chain) wanted.push_back({id, true});
    recipe.effects = loaded_only(wanted, registry, RecipeProblem::CHAIN, problems);
    recipe.chosen = wanted.empty() || !recipe.effects.empty();
  }
  if (!recipe.chosen && preset.chain) {
    recipe.effects = loaded_only(*preset.chain, registry, RecipeProblem::PRESET, problems);
    recipe.chosen = preset.chain->empty() || !recipe.effects.empty();
  }
  if (!recipe.chosen && without == WithoutChain::DEFAULT_CHAIN)
    for (const auto& id : default_chain(registry)) recipe.effects.push_back({id, true});

  // Values are checked in a store shaped like the chain ("bloom#2" needs a second bloom), the
  // way the host's own store will be.
  host::ParamStore store = store_for(recipe.effects, registry);
  if (!preset.parameters_json.empty()) {
    if (store.from_json(preset.parameters_json, &error)) recipe.parameters_json = preset.parameters_json;
    else problems->push_back({RecipeProblem::PRESET, preset_path + ": parameters: " + error});
  }
  // A ReShade preset's values: those no loaded effect has are named in one problem.
  std::vector<std::string> applied;
  std::vector<std::string> left_out = apply_preset_assignments(store, preset.assignments, &applied);
  recipe.sets.insert(recipe.sets.begin(), applied.begin(), applied.end());
  if (!left_out.empty()) {
    std::string names;
    for (const auto& a : left_out) names += (names.empty() ? "" : ", ") + a.substr(0, a.find('='));
    problems->push_back({RecipeProblem::PRESET, preset_path + ": not found, left out: " + names});
  }
  recipe.source_definitions = preset.source_definitions;
  for (const auto& note : preset.notes) notes->push_back(preset_path + ": " + note);
  for (const auto& assignment : sets) {
    std::string note;
    if (!store.set_assignment(assignment, &error, &note)) {
      problems->push_back({RecipeProblem::SET, error});
      continue;
    }
    recipe.sets.push_back(assignment);
    if (!note.empty()) notes->push_back(assignment + ": " + note);
  }
  return recipe;
}

std::vector<std::string> apply_preset_assignments(host::ParamStore& store, const std::vector<std::vector<std::string>>& assignments,
                                                  std::vector<std::string>* applied) {
  std::vector<std::string> left_out;
  for (const auto& alternatives : assignments) {
    bool done = false;
    for (const auto& assignment : alternatives) {
      std::string error, note;
      if (store.set_assignment(assignment, &error, &note)) {
        if (applied) applied->push_back(assignment);
        done = true;
        break;
      }
    }
    if (!done && !alternatives.empty()) left_out.push_back(alternatives.front());
  }
  return left_out;
}

std::vector<std::string> drop_unloaded_reshade_effects(Preset& preset, const host::PluginRegistry& registry) {
  std::vector<std::string> dropped;
  if (!preset.from_reshade || !preset.chain) return dropped;
  std::vector<PresetEffect> kept;
  for (const auto& effect : *preset.chain)
    if (registry.find_effect(effect.id)) kept.push_back(effect);
    else dropped.push_back(effect.id);
  preset.chain = kept;
  return dropped;
}

bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes, const std::string& set_origin) {
  for (const auto& effect : recipe.effects) {
    if (!chain->add(effect.id, error)) return false;
    chain->set_enabled(chain->size() - 1, effect.enabled);
  }
  if (!chain->set_source_definitions(recipe.source_definitions, error)) {
    *error = "preset PreprocessorDefinitions: " + *error;
    return false;
  }
  // Values after the chain: "bloom#2" exists once the chain holds a second bloom.
  return apply_recipe_values(recipe, params, error, notes, set_origin);
}

bool apply_recipe_values(const ChainRecipe& recipe, host::ParamStore* params, std::string* error,
                         std::vector<std::string>* notes, const std::string& set_origin) {
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
    if (!note.empty() && notes) notes->push_back(set_origin + " " + assignment + ": " + note);
  }
  return true;
}

bool chain_holds_recipe(const host::Chain& chain, const ChainRecipe& recipe) {
  if (chain.size() != recipe.effects.size() || chain.source_definitions() != recipe.source_definitions) return false;
  for (size_t i = 0; i < chain.size(); ++i)
    if (chain.effect_id(i) != recipe.effects[i].id) return false;
  return true;
}

bool replace_recipe_values(const ChainRecipe& recipe, const host::PluginRegistry& registry, host::ParamStore* params,
                           std::string* error, std::vector<std::string>* notes, const std::string& set_origin) {
  host::ParamStore fresh = store_for(recipe.effects, registry);
  if (!apply_recipe_values(recipe, &fresh, error, notes, set_origin)) return false;
  *params = std::move(fresh);
  return true;
}

bool any_enabled(const host::Chain& chain) {
  for (size_t i = 0; i < chain.size(); ++i)
    if (chain.enabled(i)) return true;
  return false;
}

}  // namespace pfx::app
