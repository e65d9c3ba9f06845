// PFX_REFERENCE_IDEAL of "dof" for image inputs (the scatter reference of docs/effects/dof.md): a scatter in double
// precision. Every pixel spreads its colour uniformly over its own CoC disc (diameter |CoC|, at least
// one pixel; the disc's edge antialiased over one pixel and its weights summing to 1 on the pixel
// grid, so energy is kept). At each output pixel the discs covering it are taken front to back by
// depth, each filling its share of the pixel until the pixel is full; a pixel that ends up less
// than full (at the frame's border, or where nothing covers it completely) is normalised.
// Colours are made safe first (as every mode does), and the alpha channel is the input's.
//
// What it cannot know is what the pinhole frame hides: the background behind a blurred foreground's
// edge. The lens-sampled scene (dof_scene.hpp) has it; this reference is for real images.
#pragma once

#include <pfx/effect.h>

#include "dof_params.hpp"

namespace pfx_dof {

// color/output: width * height RGBA, depth: width * height, rows bottom first. Uses every hardware
// thread. Throws std::bad_alloc when out of memory.
void evaluate_scatter_reference(const Settings& settings, const pfx_frame& frame, const float* color,
                                const float* depth, float* output);

}  // namespace pfx_dof
