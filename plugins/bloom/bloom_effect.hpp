// The "bloom" effect descriptor (GPU side).
#pragma once

#include <pfx/effect.h>

namespace pfx_bloom {

extern const pfx_effect_desc kBloomEffect;

}  // namespace pfx_bloom
