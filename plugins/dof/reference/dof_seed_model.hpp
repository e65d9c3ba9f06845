// PFX_REFERENCE_MODEL of the "seed" mode: the GPU passes' algorithm in double precision, with the
// same half-size copy (bilinear, edge-clamped, stored as half floats), the same 16 taps read with
// GL_LINEAR filtering, and the same mix from sharp to blurred as |CoC| passes 1 px. Left out: the
// GPU's own rounding (float arithmetic, filter weight precision), which the tests bound.
#pragma once

#include <pfx/effect.h>

#include "dof_params.hpp"

namespace pfx_dof {

// color/output: width * height RGBA, depth: width * height, rows bottom first (GL textures).
// Throws std::bad_alloc when out of memory.
void evaluate_seed_model(const Settings& settings, const pfx_frame& frame, const float* color, const float* depth,
                         float* output);

// The half-size copy's size: every full-resolution pixel has a half texel (odd sides round up).
inline int half_size(int full) { return (full + 1) / 2; }

}  // namespace pfx_dof
