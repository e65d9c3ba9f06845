// The checks the loader makes on an effect descriptor before accepting a plugin, so the rest of
// the runtime can trust ids, callbacks and parameter ranges. pfx-validate checks far more.
#pragma once

#include <string>

#include <pfx/effect.h>
#include <pfx/importer.h>

namespace pfx::host {

// Empty when the descriptor is usable; otherwise one sentence naming the effect and parameter.
std::string check_effect_descriptor(const pfx_effect_desc* desc);
std::string check_param_descriptor(const pfx_param_desc& param);
// Importers: id [a-z0-9_]+, at least one extension (lower case, no dot), import and release set.
std::string check_importer_descriptor(const pfx_importer_desc* desc);
// Non-empty [a-z0-9_]+: the form of effect, parameter, enum item and importer ids.
bool is_identifier(const char* text);
// Number of meaningful components of a value of this type (1 for float/int/bool/enum, 2, 3).
int param_component_count(pfx_param_type type);

}  // namespace pfx::host
