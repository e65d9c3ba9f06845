#pragma once
// One FX technique as a pfx effect: the descriptor (fill_effect_desc) and the instance behind it.
#include <cstddef>

#include "fx_catalog.hpp"

namespace pfx_fx {

class FxInstance;

// The most techniques one process offers: the effect descriptor's create() says nothing of which
// effect it creates, so each effect gets its own create function from a table of this size.
constexpr std::size_t kMaxEffects = 2048;

// Points the descriptor at the entry's strings and parameters and at the functions of effect
// number `index` of the catalog.
void fill_effect_desc(FxEffectEntry& entry, std::size_t index);

// `instance` when it is one this plugin's create made and destroy has not yet destroyed, else
// null: calls that reach the plugin through another factory than the effect's own
// (set_definitions) get no pointer of another plugin's.
FxInstance* live_instance(void* instance);

}  // namespace pfx_fx
