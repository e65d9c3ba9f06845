// PFX_REFERENCE_IDEAL of the "bloom" effect: what each mode approximates, computed exactly in
// double precision at full resolution. The bright part is taken of every pixel (made safe as the
// GPU does: NaN -> 0, negative -> 0, at most the firefly clamp), times strength and tint, and
// convolved with the mode's point spread function (psf.hpp) over a black surround: the
// shift-invariant bloom the mode's pyramid, downscale or truncation only approximates. The frame is
// then composited as the mode does (times tone_scale for gaussian), clamped to +-65504.
#pragma once

#include <cstdint>

#include "bloom_params.hpp"

namespace pfx_bloom {

// As evaluate_model: RGBA, rows bottom first; no-op settings copy the frame. Throws std::bad_alloc.
void evaluate_ideal(const Settings& settings, uint32_t width, uint32_t height, const float* color, float* output);

}  // namespace pfx_bloom
