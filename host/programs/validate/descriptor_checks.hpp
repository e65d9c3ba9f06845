// What pfx-validate requires of descriptors, as pure functions over the structs (no plugin, no
// GL), so they can be tested on hand-made descriptors. Stricter than the loader in libpfxhost,
// which refuses only what would break the runtime: here labels, tooltips and display ranges
// count too, because a host's UI shows them.
#pragma once

#include <string>
#include <vector>

#include <pfx/pfx.h>

namespace pfx::validate {

// "org.pfx.bloom": two or more dot-separated parts of [a-z0-9_-].
bool is_plugin_id(const char* id);
// "bloom", "threshold": [a-z0-9_]+.
bool is_effect_or_param_id(const char* id);

// One sentence per problem, naming the parameter ("parameter 'threshold': default 5 is above hard_max 4").
std::vector<std::string> param_descriptor_problems(const pfx_param_desc& param);
// The effect's own fields, then every parameter (and repeated parameter ids).
std::vector<std::string> effect_descriptor_problems(const pfx_effect_desc& effect);

}  // namespace pfx::validate
