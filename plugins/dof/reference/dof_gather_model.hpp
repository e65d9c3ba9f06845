// PFX_REFERENCE_MODEL of the "gather" mode: the GPU passes' algorithm in double precision, with the
// same work image (half or full resolution, stored as half floats), the same 16 px tiles and
// dilation, the same ring samples read texel by texel, the same near/far weights and the same
// CoC-weighted upsampling. Left out: the GPU's float arithmetic, which the tests bound.
#pragma once

#include <pfx/effect.h>

#include "dof_params.hpp"

namespace pfx_dof {

// color/output: width * height RGBA, depth: width * height, rows bottom first (GL textures).
// Throws std::bad_alloc when out of memory.
void evaluate_gather_model(const Settings& settings, const pfx_frame& frame, const float* color, const float* depth,
                           float* output);

}  // namespace pfx_dof
