// The four settings every chain adapter offers (the frei0r plugin pfx_chain's parameters, the
// GStreamer element's properties), as text, and what they mean: docs/hosts.md.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_builder.hpp"
#include "display_transfer.hpp"

namespace pfx::adapters {

// The chain an adapter runs when neither its chain setting nor a preset names one.
constexpr const char* kAdapterDefaultChain = "bloom";

struct ChainSettings {
  // Effect ids in order, separated by ','; "none": no effect (the frame is copied in and out);
  // "" (the default): the preset's chain, else kAdapterDefaultChain.
  std::string chain;
  // "effect.param=value" assignments separated by ';' (a value may hold ','), after the preset.
  std::string set;
  std::string transfer = "srgb";  // srgb | linear: how the frame's 8-bit values relate to light ("": srgb)
  std::string preset;             // a preset file (pfx-view's JSON or ReShade's .ini), or ""
};

// What a frame needs from the settings: the transfer and the chain's recipe (the preset read).
// What of the preset does not apply is left out and named in recipe->left_out, in every host
// (chain_builder.hpp's preset policy). False with *error naming the setting and the problem for a
// chain effect or assignment that does not apply or a preset that does not read. With `left_out`,
// those are left out of the recipe instead and added there (describe_problems words them), as
// pfx-inject does; only a bad transfer still fails.
bool resolve_chain_settings(const ChainSettings& settings, const host::PluginRegistry& registry,
                            app::Transfer* transfer, app::ChainRecipe* recipe, std::string* error,
                            std::vector<app::RecipeProblem>* left_out = nullptr);

// Each problem as "chain: MESSAGE", "set: MESSAGE" or "preset: MESSAGE", after the setting it
// came from.
std::vector<std::string> describe_problems(const std::vector<app::RecipeProblem>& problems);

// "a=1; b=2;;" -> {"a=1", "b=2"}: split at ';', blanks around each item dropped, empty items too.
std::vector<std::string> split_assignments(const std::string& text);

}  // namespace pfx::adapters
