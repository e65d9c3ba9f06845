// The filters pfx-obs offers: one per effect that needs nothing but colour (colour_only.hpp),
// whose properties are the effect's parameters, and "pfx chain", whose properties are the chain
// adapters' four settings (chain_settings.hpp). What each kind's settings mean as a chain.
#pragma once

#include <string>
#include <vector>

#include <obs-module.h>
#include <pfx/effect.h>
#include <pfx/host/plugin_registry.hpp>

#include "chain_settings.hpp"

namespace pfx::obs {

struct FilterKind {
  std::string type_id;  // OBS's id: "pfx_bloom_filter", "pfx_chain_filter"
  std::string name;     // shown in OBS's filter menu
  const pfx_effect_desc* effect = nullptr;  // null: the chain filter
  const pfx::host::Plugin* plugin = nullptr;  // the effect's
};

// The properties OBS shows, from the parameters' descriptions (names, explanations, units,
// slider ranges, enum items). With the size of the filter's source (0 when OBS asks without a
// filter), parameters that follow the frame size (PFX_PARAM_FOLLOWS_FRAME_SIZE) get their slider
// range at that size, and their explanation says so.
obs_properties_t* kind_properties(const FilterKind& kind, uint32_t width = 0, uint32_t height = 0);
// The defaults: each parameter's display-referred default (an 8-bit SDR frame holds nothing
// above 1.0); the chain filter's: bloom, srgb.
void kind_defaults(const FilterKind& kind, obs_data_t* settings);
// The chain a filter's settings ask for.
adapters::ChainSettings kind_chain_settings(const FilterKind& kind, obs_data_t* settings);

}  // namespace pfx::obs
