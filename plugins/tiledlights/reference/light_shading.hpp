// CPU references of the "tiledlights" effect, in double precision (pfx/reference.h):
//   model: the windowed sum the GPU computes in every mode,
//          base + albedo * sum_i radiance_i * max(N.L_i, 0) / (1 + d_i^2) * (1 - smoothstep(0.75 r_i, r_i, d_i));
//   ideal: the same without the window and the range: every light at every pixel, the physical
//          answer the cutoff approximates.
// Pixels without geometry (view depth not finite and > 0) keep the incoming colour. Colour, emissive
// and albedo samples are read through the nonfinite setting first.
#pragma once

#include <string>

#include <pfx/effect.h>

#include "tiledlights_params.hpp"

namespace pfx_tiledlights {

// Frame-sized images, rows bottom first, RGBA interleaved (depth: one float per pixel, encoded as
// frame.depth_encoding says). emissive may be null unless settings.base is emissive.
struct GBufferImages {
  const float* color = nullptr;
  const float* depth = nullptr;
  const float* normal = nullptr;
  const float* albedo = nullptr;
  const float* emissive = nullptr;
};

// Writes width * height * 4 floats. False with *error for bad lights or a non-perspective camera.
bool shade_reference(const pfx_frame& frame, const Settings& settings, const GBufferImages& images, bool windowed,
                     float* output, std::string* error);

}  // namespace pfx_tiledlights
