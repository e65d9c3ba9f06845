#include "chain_builder.hpp"

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "default_chain.hpp"
#include "plugin_listing.hpp"

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
  // The first chain given: the setting's, then the preset's (what of it is loaded, even nothing).
  // An empty given chain ("none") is a choice too: no effect.
  const std::vector<std::string> unloaded = drop_unloaded_effects(preset, registry);
  if (chain) {
    std::vector<PresetEffect> wanted;
    for (const auto& id : *chain) wanted.push_back({id, true});
    recipe.effects = loaded_only(wanted, registry, RecipeProblem::CHAIN, problems);
    recipe.chosen = wanted.empty() || !recipe.effects.empty();
  }
  const bool preset_chain = !recipe.chosen && preset.chain;
  if (preset_chain) {
    recipe.effects = *preset.chain;
    recipe.chosen = true;
  }
  if (!recipe.chosen && without == WithoutChain::DEFAULT_CHAIN)
    for (const auto& id : default_chain(registry)) recipe.effects.push_back({id, true});

  // Values are checked in a store shaped like the chain ("bloom#2" needs a second bloom), the
  // way the host's own store will be.
  host::ParamStore store = store_for(recipe.effects, registry);
  PresetValues applied;
  recipe.left_out = preset_left_out_warning(preset_path, preset_chain ? unloaded : std::vector<std::string>{},
                                            apply_preset_values(store, preset, &applied));
  recipe.parameters_json = applied.parameters_json;
  recipe.sets = applied.assignments;
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

namespace {

// The store's reason in a few words: its message without the key it names.
std::string short_reason(const std::string& key, const std::string& message) {
  if (message.rfind("unknown effect", 0) == 0) return "not loaded";
  if (message.find("has no parameter") != std::string::npos) return "no such parameter";
  const std::string prefix = key + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// For "effect.param=v1,v2": whether the parameter's component count differs from the numbers
// given (then *reason says so). Parameters of one number, and unknown ones, are the store's to judge.
bool wrong_count(const host::ParamStore& store, const std::string& key, const std::string& value, std::string* reason) {
  const size_t dot = key.find('.');
  if (dot == std::string::npos) return false;
  const pfx_param_desc* desc = store.descriptor(key.substr(0, dot), key.substr(dot + 1));
  if (!desc) return false;
  const size_t components = static_cast<size_t>(component_count(desc->type));
  const size_t given = static_cast<size_t>(std::count(value.begin(), value.end(), ',')) + 1;
  if (components == 1 || given == components) return false;
  *reason = "expects " + std::to_string(components) + " numbers, got " + std::to_string(given);
  return true;
}

// A ReShade preset's values (Preset::assignments), each by the first of its alternatives that
// applies.
void apply_assignments(host::ParamStore& store, const std::vector<std::vector<std::string>>& assignments,
                       std::vector<std::string>* applied, std::vector<LeftOutValue>* left_out) {
  for (const auto& alternatives : assignments) {
    std::string first_reason;
    bool done = false;
    for (const auto& assignment : alternatives) {
      const size_t equals = assignment.find('=');
      const std::string key = assignment.substr(0, equals);
      std::string error, note, reason;
      if (equals == std::string::npos || !wrong_count(store, key, assignment.substr(equals + 1), &reason)) {
        if (store.set_assignment(assignment, &error, &note)) {
          applied->push_back(assignment);
          done = true;
          break;
        }
        reason = short_reason(key, error);
      }
      if (first_reason.empty()) first_reason = reason;
    }
    if (!done && !alternatives.empty())
      left_out->push_back({alternatives.front().substr(0, alternatives.front().find('=')), first_reason});
  }
}

// A pfx preset's values ({"bloom": {"strength": 2}}), one by one: the store takes them from JSON
// (the text rules of --set), and one that does not apply leaves the others.
void apply_parameters(host::ParamStore& store, const std::string& json, std::string* applied_json,
                      std::vector<LeftOutValue>* left_out) {
  if (json.empty()) return;
  nlohmann::ordered_json applied = nlohmann::ordered_json::object();
  const nlohmann::ordered_json given = nlohmann::ordered_json::parse(json);
  for (const auto& [instance, params] : given.items()) {
    if (!params.is_object()) {
      left_out->push_back({instance, "not an object of parameters"});
      continue;
    }
    for (const auto& [param, value] : params.items()) {
      const nlohmann::ordered_json one = {{instance, {{param, value}}}};
      std::string error;
      if (store.from_json(one.dump(), &error)) applied[instance][param] = value;
      else left_out->push_back({instance + "." + param, short_reason(instance + "." + param, error)});
    }
  }
  if (!applied.empty()) *applied_json = applied.dump();
}

}  // namespace

std::vector<LeftOutValue> apply_preset_values(host::ParamStore& store, const Preset& preset, PresetValues* applied) {
  PresetValues kept;
  std::vector<LeftOutValue> left_out;
  apply_parameters(store, preset.parameters_json, &kept.parameters_json, &left_out);
  apply_assignments(store, preset.assignments, &kept.assignments, &left_out);
  if (applied) *applied = std::move(kept);
  return left_out;
}


std::string preset_left_out_warning(const std::string& preset_path, const std::vector<std::string>& unloaded_effects,
                                    const std::vector<LeftOutValue>& values) {
  std::string named;
  for (const auto& effect : unloaded_effects) named += (named.empty() ? "" : ", ") + effect + " (not loaded)";
  for (const auto& value : values) named += (named.empty() ? "" : ", ") + value.key + " (" + value.reason + ")";
  return named.empty() ? "" : preset_path + ": left out: " + named;
}

std::vector<std::string> drop_unloaded_effects(Preset& preset, const host::PluginRegistry& registry) {
  std::vector<std::string> dropped;
  if (!preset.chain) return dropped;
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
