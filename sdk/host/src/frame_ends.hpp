// Where the chain meets the host: how the host's colour becomes the first effect's "color" and the
// last effect's "output" becomes the host's output, given the encodings the two effects work in.
// A linear effect that promised PFX_DECLARATION_SAMPLES_AND_DRAWS takes a host's 8-bit texture as
// it is (an sRGB one decodes when sampled and encodes when drawn into); a display-referred one
// (PFX_DECLARATION_DISPLAY_REFERRED) takes an 8-bit sRGB texture through a raw view of its codes,
// and a framebuffer holding sRGB codes as it is. Anything else costs one step of the chain's
// (ColorStep, OutputStep), run and reported as a pass of "chain".
#pragma once

#include <string>

#include "chain_internal.hpp"

namespace pfx::host {

// Fills the binding and step fields of `resources` for a chain whose first and last effects
// declared `first` and `last` (the same declaration for a chain of one); `reads_output`: a pass
// of the last effect samples its own "output", which a framebuffer cannot be. Makes this frame's
// raw views; release_frame_views deletes them.
void choose_frame_ends(const Declaration& first, const Declaration& last, bool reads_output,
                       FrameConversion& conversion, FrameResources* resources);
void release_frame_views(FrameResources* resources);

// Runs the step before the first pass and the one after the last; the pass name to report in
// *name ("" when the step is AS_IS). False with *error.
bool run_color_step(FrameResources& resources, FrameConversion& conversion, std::string* name, std::string* error);
bool run_output_step(const FrameResources& resources, GlPool& pool, FrameConversion& conversion, std::string* name,
                     std::string* error);

}  // namespace pfx::host
