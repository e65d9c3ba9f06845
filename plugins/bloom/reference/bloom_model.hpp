// PFX_REFERENCE_MODEL of the "bloom" effect: the GPU passes' algorithm in double precision, with
// the same level sizes, the same tap positions, bilinear filtering done as GL_LINEAR does it, the
// same wrap modes and the same treatment of NaN, infinite, negative and too-bright input. Only the
// GPU's rounding (half-float storage, filter weight precision) is left out: the tests bound that.
#pragma once

#include <cstdint>

#include "bloom_params.hpp"

namespace pfx_bloom {

// color and output: width * height RGBA, rows bottom first (as GL textures). output may not alias
// color. Throws std::bad_alloc when out of memory.
void evaluate_chain_model(const Settings& settings, uint32_t width, uint32_t height, const float* color,
                          float* output);

}  // namespace pfx_bloom
