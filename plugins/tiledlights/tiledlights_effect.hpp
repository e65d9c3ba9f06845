// The "tiledlights" effect descriptor (GPU side).
#pragma once

#include <pfx/effect.h>

namespace pfx_tiledlights {

extern const pfx_effect_desc kTiledLightsEffect;

}  // namespace pfx_tiledlights
