// The checks the loader makes on an effect descriptor before accepting a plugin, so the rest of
// the runtime can trust ids, callbacks and parameter ranges. pfx-validate checks far more.
#pragma once

#include <string>

#include <pfx/effect.h>

namespace pfx::host {

// Empty when the descriptor is usable; otherwise one sentence naming the effect and parameter.
std::string check_effect_descriptor(const pfx_effect_desc* desc);
std::string check_param_descriptor(const pfx_param_desc& param);
// Number of meaningful components of a value of this type (1 for float/int/bool/enum, 2, 3).
int param_component_count(pfx_param_type type);

}  // namespace pfx::host
