#pragma once
// One FX technique as a pfx effect: the descriptor (fill_effect_desc) and the instance behind it.
#include <cstddef>

#include "fx_catalog.hpp"

namespace pfx_fx {

// The most techniques one process offers: the effect descriptor's create() says nothing of which
// effect it creates, so each effect gets its own create function from a table of this size.
constexpr std::size_t kMaxEffects = 2048;

// Points the descriptor at the entry's strings and parameters and at the functions of effect
// number `index` of the catalog.
void fill_effect_desc(FxEffectEntry& entry, std::size_t index);

}  // namespace pfx_fx
