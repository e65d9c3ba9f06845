// Which effects a host runs and with what values, read the way every pfx host of 8-bit frames
// reads them (pfx-inject, the video-host adapters): a preset gives the chain and values, an
// explicit chain replaces the preset's, assignments ("effect.param=value") override values.
//
// A recipe is checked against the loaded effects' descriptors without any GL, so a launcher can
// refuse a bad chain, preset or assignment before anything runs, and a host whose settings a user
// may have set by hand can leave out only what is wrong and run the rest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "preset.hpp"

namespace pfx::app {

struct ChainRecipe {
  std::vector<PresetEffect> effects;
  // False when nobody chose the chain (no chain given, none in the preset): the host's default
  // (WithoutChain), and pfx-inject leaves out effects that need inputs an application cannot give.
  bool chosen = false;
  std::string parameters_json;    // the preset's values, or empty
  std::vector<std::string> sets;  // assignments that apply, in order
  std::string source_definitions;  // the preset's, for the effects made from source files
  // What of the preset did not apply, as the one warning of its load (preset_left_out_warning):
  // every host says it once and runs the rest; "" when all of it applied.
  std::string left_out;
};

// The one preset policy of every pfx host (docs/fx.md, "Presets"): what a preset names that is
// loaded and fits runs with its values; what is not there or does not fit is left out and named in
// one warning per preset load, with the reason. A preset that does not read at all is an error.
// The three steps: drop_unloaded_effects, apply_preset_values, preset_left_out_warning.

// A preset value that does not apply: its key ("fx_vibrance.vibrance") and why, in a few words
// ("no such parameter", "not loaded", "'abc' is not a number", "expects 3 numbers, got 1").
struct LeftOutValue {
  std::string key, reason;
};

// The preset's chain without the effects no loaded plugin has (returned, for the warning).
std::vector<std::string> drop_unloaded_effects(Preset& preset, const host::PluginRegistry& registry);

// What of a preset's values applied, to hand on (ChainRecipe) or to count as set (Python).
struct PresetValues {
  std::string parameters_json;           // a pfx preset's values that applied, or ""
  std::vector<std::string> assignments;  // a ReShade preset's values that applied, in order
};

// Applies the preset's values to `store` (shaped like the chain: "bloom#2" needs a second bloom),
// each one by itself: a pfx preset's "parameters", then a ReShade preset's assignments, each by the
// first of its alternatives that applies. Returns the values left out, with the reason the first
// alternative gave. A vector parameter given another count of numbers than it has is left out
// too: a ReShade preset writes every component, so fewer are a mistake, not a splat.
std::vector<LeftOutValue> apply_preset_values(host::ParamStore& store, const Preset& preset,
                                              PresetValues* applied = nullptr);

// The one warning of a preset load, every host's: "look.ini: left out: fx_missing (not loaded),
// fx_vibrance.vibrance ('abc' is not a number)"; empty when everything applied.
std::string preset_left_out_warning(const std::string& preset_path, const std::vector<std::string>& unloaded_effects,
                                    const std::vector<LeftOutValue>& values);

struct RecipeProblem {
  enum Source { CHAIN, PRESET, SET } source;
  std::string message;
};

// What runs when neither the chain nor the preset names effects.
enum class WithoutChain {
  DEFAULT_CHAIN,  // every effect found, in the default order (default_chain.hpp)
  NO_EFFECT       // nothing: the frame passes through
};

// Reads the preset (when preset_path is not empty) and checks the chain's effect ids, the preset's
// values and every assignment against the loaded effects. What of the preset does not apply is
// left out and named in recipe.left_out (the preset policy above). The other problems are left
// out and described in *problems: an unknown effect of the given chain leaves it (a given chain
// left with none gives way to the preset's, then the default), a preset that does not read is not
// used, an assignment that does not apply is dropped. *notes gets the store's remarks on values it
// adjusted (clamped). Hosts that must refuse rather than leave out treat any problem as an error.
ChainRecipe make_chain_recipe(const std::string& preset_path, const std::optional<std::vector<std::string>>& chain,
                              const std::vector<std::string>& sets, const host::PluginRegistry& registry,
                              WithoutChain without, std::vector<RecipeProblem>* problems,
                              std::vector<std::string>* notes);
// Fills an empty chain and its store, the chain with the recipe's source definitions; false with
// *error naming the effect, the definitions or the assignment (an assignment's error starts with
// `set_origin`, the option that gave it). *notes, when given, gets
// the store's remarks on assignments it adjusted.
bool build_chain(const ChainRecipe& recipe, host::Chain* chain, host::ParamStore* params, std::string* error,
                 std::vector<std::string>* notes = nullptr, const std::string& set_origin = "--set");
// The recipe's values (the preset's, then the assignments) put into a store that already holds
// the chain's instances; false with *error as build_chain's.
bool apply_recipe_values(const ChainRecipe& recipe, host::ParamStore* params, std::string* error,
                         std::vector<std::string>* notes = nullptr, const std::string& set_origin = "--set");
// Whether `chain` holds the recipe's effects, in its order, with its preprocessor definitions: then a
// new recipe changes only values and flags (replace_recipe_values), and no effect is made again.
bool chain_holds_recipe(const host::Chain& chain, const ChainRecipe& recipe);
// For such a chain: a store filled with the recipe's values as build_chain fills a new one, put in
// place of `params`, the store the chain reads. All or nothing: false with *error as build_chain's.
bool replace_recipe_values(const ChainRecipe& recipe, const host::PluginRegistry& registry, host::ParamStore* params,
                           std::string* error, std::vector<std::string>* notes = nullptr,
                           const std::string& set_origin = "--set");
// Whether any effect of the chain is switched on: with none, a host has nothing to run.
bool any_enabled(const host::Chain& chain);
// Every loaded effect's values at the display-referred defaults, with as many instances of each as
// `effects` holds (at least one): the store a chain of those effects on 8-bit frames starts from.
host::ParamStore store_for(const std::vector<PresetEffect>& effects, const host::PluginRegistry& registry);
// "bloom, dof, glare": the loaded effects' ids, for messages.
std::string loaded_effect_ids(const host::PluginRegistry& registry);

}  // namespace pfx::app
