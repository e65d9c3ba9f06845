// PFX_REFERENCE_MODEL of the "bloom" effect: each mode's GPU passes in double precision, with the
// same level sizes, the same tap positions, bilinear filtering done as GL_LINEAR does it, the same
// wrap modes and the same treatment of NaN, infinite, negative and too-bright input. Only the GPU's
// rounding (half-float storage, filter weight precision) is left out: the tests bound that.
#pragma once

#include <cstdint>

#include "bloom_params.hpp"

namespace pfx_bloom {

// What the GPU's rounding can act on, for the tests' tolerance: the largest value any target holds
// at any time, and the most half-float stores a value passes through from the frame to the output
// (the output's own store included).
struct ModelTrace {
  double largest_stored = 0;
  int stores = 0;
};

// color and output: width * height RGBA, rows bottom first (as GL textures). output may not alias
// color. Any mode; with no-op settings the output is the input, as the host copies it. Throws
// std::bad_alloc when out of memory.
void evaluate_model(const Settings& settings, uint32_t width, uint32_t height, const float* color, float* output,
                    ModelTrace* trace = nullptr);

// The modes one by one (evaluate_model picks), for settings that are not a no-op.
void evaluate_chain_model(const Settings& settings, uint32_t width, uint32_t height, const float* color, float* output,
                          ModelTrace& trace);
void evaluate_gaussian_model(const Settings& settings, uint32_t width, uint32_t height, const float* color,
                             float* output, ModelTrace& trace);
void evaluate_mgf_model(const Settings& settings, uint32_t width, uint32_t height, const float* color, float* output,
                        ModelTrace& trace);

}  // namespace pfx_bloom
