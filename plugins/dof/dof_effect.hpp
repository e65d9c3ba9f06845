// The "dof" effect descriptor (GPU side).
#pragma once

#include <pfx/effect.h>

namespace pfx_dof {

extern const pfx_effect_desc kDofEffect;

}  // namespace pfx_dof
