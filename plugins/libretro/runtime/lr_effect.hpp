#pragma once
// One libretro preset as a pfx effect: the descriptor (fill_effect_desc) and the instance behind it.
#include <cstddef>

#include "lr_catalog.hpp"

namespace pfx_libretro {

// The most presets one process offers: the effect descriptor's create() says nothing of which
// effect it creates, so each effect gets its own create function from a table of this size
// (libretro/slang-shaders holds about 2,500 presets).
constexpr std::size_t kMaxEffects = 4096;

// Points the descriptor at the entry's strings and parameters and at the functions of effect
// number `index` of the catalog.
void fill_effect_desc(LrEffectEntry& entry, std::size_t index);

}  // namespace pfx_libretro
