// PFX_REFERENCE_MODEL of the "glare" effect: its passes in double precision (same buffer size, tap
// positions, bilinear filtering as GL_LINEAR, wrap modes, bad-value handling).
#pragma once

#include <cstdint>

#include "glare_params.hpp"
#include "reference/bloom_model.hpp"

namespace pfx_bloom {

// As evaluate_model (bloom_model.hpp): RGBA, rows bottom first; no-op settings copy the frame.
void evaluate_glare_model(const GlareSettings& settings, uint32_t width, uint32_t height, const float* color,
                          float* output, ModelTrace* trace = nullptr);

}  // namespace pfx_bloom
