// What --list prints: every loaded plugin, its effects and every parameter with its metadata,
// as aligned text or as JSON. Shared by our programs so they all describe plugins the same way.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::app {

// How many numbers a value of the type holds: 3 for a colour or vec3, 2 for a vec2, else 1.
int component_count(pfx_param_type type);
// A parameter's value as text: the item id of an enum, true/false, "%g" numbers joined by ','.
std::string value_text(const pfx_param_desc& param, const pfx_value& value);
// Its (scene-referred) default as text.
std::string default_value_text(const pfx_param_desc& param);
// Whether it has a default of its own for display-referred frames (pfx_param_desc.display_default).
bool has_display_default(const pfx_param_desc& param);
// The JSON --list --json gives: a value (an enum's item id, a bool, a number, an array for
// vectors), one parameter's description, one effect with all its parameters.
nlohmann::ordered_json value_json(const pfx_param_desc& param, const pfx_value& value);
nlohmann::ordered_json parameter_json(const pfx_effect_desc& effect, const pfx_param_desc& param);
nlohmann::ordered_json effect_json(const pfx_effect_desc& effect);
std::string plugin_listing_text(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& load_errors);
std::string plugin_listing_json(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& load_errors);

}  // namespace pfx::app
