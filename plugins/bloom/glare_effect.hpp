// The "glare" effect descriptor (GPU side): Kawase's star streaks.
#pragma once

#include <pfx/effect.h>

namespace pfx_bloom {

extern const pfx_effect_desc kGlareEffect;

}  // namespace pfx_bloom
