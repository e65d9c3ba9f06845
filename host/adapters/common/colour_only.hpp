// Which effects need nothing but colour, told from what each declares: an instance is made (so a
// GL context must be current) and asked, at its display-referred defaults, for the passes of a
// frame that offers every input (depth, normal, albedo, emissive, lights); an effect whose passes
// read the colour and its own targets alone, and ask for nothing more, runs on video frames.
// Those get a frei0r plugin and an OBS filter of their own.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::adapters {

struct EffectInputs {
  std::string id;
  bool colour_only = false;
  std::vector<std::string> needs;  // inputs other than colour it asked for ("depth", "lights")
  std::string error;               // the instance could not be made or declared
};

// Every effect of the registry, in load order.
std::vector<EffectInputs> classify_effects(const host::PluginRegistry& registry);

}  // namespace pfx::adapters
