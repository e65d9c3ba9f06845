#include "host_layout.hpp"

namespace pfx::host {

std::unique_ptr<HostLayoutEffect> effect_in_host_layout(const pfx_effect_desc* plugin_desc, std::string* problem) {
  if (!plugin_desc) {
    *problem = "NULL descriptor";
    return nullptr;
  }
  if (plugin_desc->struct_size < PFX_EFFECT_DESC_MIN_SIZE) {
    *problem = "descriptor struct too small (" + std::to_string(plugin_desc->struct_size) + " bytes, the first published size is " +
               std::to_string(PFX_EFFECT_DESC_MIN_SIZE) + ")";
    return nullptr;
  }
  auto effect = std::make_unique<HostLayoutEffect>();
  effect->desc = read_sized(plugin_desc);
  if (effect->desc.param_count && !effect->desc.params) {
    *problem = std::string("effect '") + (effect->desc.id ? effect->desc.id : "(null)") + "': param_count without params";
    return nullptr;
  }
  effect->params = read_sized_array(effect->desc.params, effect->desc.param_count, PFX_PARAM_DESC_MIN_SIZE,
                                    "parameter", problem);
  if (!problem->empty()) {
    *problem = std::string("effect '") + (effect->desc.id ? effect->desc.id : "(null)") + "': " + *problem;
    return nullptr;
  }
  effect->desc.struct_size = sizeof(pfx_effect_desc);
  for (pfx_param_desc& param : effect->params) {
    // A flag bit means nothing in a struct older than the field it announces.
    if (param.struct_size < PFX_STRUCT_SIZE_THROUGH(pfx_param_desc, display_default))
      param.flags &= ~static_cast<uint32_t>(PFX_PARAM_HAS_DISPLAY_DEFAULT);
    param.struct_size = sizeof(pfx_param_desc);
  }
  effect->desc.params = effect->params.empty() ? nullptr : effect->params.data();
  return effect;
}

}  // namespace pfx::host
