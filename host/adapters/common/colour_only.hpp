// Which effects need nothing but colour: an effect that promises it (PFX_EFFECT_COLOR_ONLY) is
// taken at its word; for the others an instance is made (so a GL context must be current) and
// asked, at its display-referred defaults, for the passes of a frame of colour alone; an effect
// that declares and asks for nothing more (its own targets aside) runs on video frames and
// applications' pictures, as it does in pfx-render. Those get a frei0r plugin and an OBS filter of
// their own. The others are asked again with a frame that offers every input (depth, normal,
// albedo, emissive, lights), to name what they need.
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
