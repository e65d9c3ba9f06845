// The OBS video filter that runs a pfx chain over its source on OBS's graphics thread: the
// source below the filter is drawn into an 8-bit texture of the source's size (following its
// size changes, alpha kept), run through the chain into a second texture (texture_filter.hpp:
// OBS's GL state is put back), which is drawn where the source would have been. Settings that do
// not build pass the source through and say why in OBS's log, once.
#pragma once

#include <memory>

#include <obs-module.h>
#include <pfx/host/plugin_registry.hpp>

#include "filter_kinds.hpp"

namespace pfx::obs {

// What OBS needs to register `kind` (its type_data points at it: it must outlive the module). The
// filters run `registry`'s effects.
obs_source_info filter_info(const FilterKind& kind);
void set_filter_registry(std::shared_ptr<const host::PluginRegistry> registry);

}  // namespace pfx::obs
