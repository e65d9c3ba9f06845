// The four settings every chain adapter offers (the frei0r plugin pfx_chain's parameters, the
// GStreamer element's properties), as text, and what they mean: docs/hosts.md.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

#include "chain_builder.hpp"
#include "display_transfer.hpp"

namespace pfx::adapters {

struct ChainSettings {
  // Effect ids in order, separated by ','; "none": no effect (the frame is copied in and out);
  // "": the preset's chain, or no effect without a preset.
  std::string chain = "bloom";
  // "effect.param=value" assignments separated by ';' (a value may hold ','), after the preset.
  std::string set;
  std::string transfer = "srgb";  // srgb | linear: how the frame's 8-bit values relate to light ("": srgb)
  std::string preset;             // a pfx-view preset file, or ""
};

// What a frame needs from the settings: the transfer and the chain's recipe (the preset read).
// False with *error naming the setting and the problem. With `left_out`, an effect, assignment or
// preset that does not apply is left out of the recipe instead and added there (describe_problems
// words them), as pfx-inject does; only a bad transfer still fails.
bool resolve_chain_settings(const ChainSettings& settings, const host::PluginRegistry& registry,
                            app::Transfer* transfer, app::ChainRecipe* recipe, std::string* error,
                            std::vector<app::RecipeProblem>* left_out = nullptr);

// Each problem as "chain: MESSAGE", "set: MESSAGE" or "preset: MESSAGE", after the setting it
// came from.
std::vector<std::string> describe_problems(const std::vector<app::RecipeProblem>& problems);

// "a=1; b=2;;" -> {"a=1", "b=2"}: split at ';', blanks around each item dropped, empty items too.
std::vector<std::string> split_assignments(const std::string& text);

}  // namespace pfx::adapters
