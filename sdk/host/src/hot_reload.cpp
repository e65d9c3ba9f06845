#include "pfx/host/hot_reload.hpp"

namespace pfx::host {

bool reload_plugin(PluginRegistry& registry, ParamStore& params, Chain& chain, const std::string& plugin_id,
                   ReloadResult* result, std::string* error) {
  const Plugin* old = registry.find_plugin(plugin_id);
  if (!old) {
    if (error) *error = "no plugin '" + plugin_id + "' is loaded";
    return false;
  }
  ReloadResult outcome;
  outcome.plugin_id = plugin_id;
  outcome.old_version = old->version;
  std::vector<std::string> old_effects;
  for (const pfx_effect_desc* desc : old->effects) old_effects.emplace_back(desc->id);

  auto adopt = [&](std::string* reason) {
    // The chain first: it is all or nothing, and it lets go of the instances of effects the new
    // version lacks, which the store may then forget. The store points into the old library:
    // re-register the effects against the new descriptors (values carried over by id and type).
    if (!chain.refresh(&outcome.effects_dropped, reason)) return false;
    for (const auto& id : old_effects) {
      if (!params.has_effect(id)) continue;
      const EffectInfo* now = registry.find_effect(id);
      if (now) params.add_effect(now->desc);
      else params.remove_effect(id);
    }
    return true;
  };
  if (!registry.reload(plugin_id, adopt, error)) return false;
  outcome.new_version = registry.find_plugin(plugin_id)->version;
  if (result) *result = outcome;
  return true;
}

}  // namespace pfx::host
