// Hot reload for a program running one chain (docs/architecture.md): load the rebuilt library
// under a fresh name, move the chain's instances and the parameter values over to it, unload the
// old one. A rebuilt plugin that cannot be loaded, or whose effects cannot be created, is refused
// and the old version keeps running. GL thread, context current (effects are created and destroyed).
#pragma once

#include <string>
#include <vector>

#include "pfx/host/api.hpp"
#include "pfx/host/chain.hpp"
#include "pfx/host/param_store.hpp"
#include "pfx/host/plugin_registry.hpp"

namespace pfx::host {

struct ReloadResult {
  std::string plugin_id;
  std::string old_version, new_version;
  // Effects that were in the chain but are not in the new version: removed from the chain and
  // from the parameter store.
  std::vector<std::string> effects_dropped;
};

// Reloads plugin `plugin_id` from its file. Parameters keep, in every instance, each value whose
// effect, id and type are unchanged (ParamStore::add_effect); new parameters start at their
// defaults. On failure
// returns false with *error "PATH: reason" and changes nothing.
PFX_HOST_API bool reload_plugin(PluginRegistry& registry, ParamStore& params, Chain& chain,
                                const std::string& plugin_id, ReloadResult* result, std::string* error);

}  // namespace pfx::host
