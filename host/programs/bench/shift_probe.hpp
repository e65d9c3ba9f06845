// How shift-invariant an effect is, measured on the GPU: a black frame holding one bright pixel,
// moved 1 px at a time over 16 positions, each run through the chain. Two figures: the
// coefficient of variation of the total light the effect adds, and the relative RMS by which the
// responses, aligned on their pixel, differ from their mean (0 for a shift-invariant effect; a
// pyramid's half-size grids make it larger).
#pragma once

#include <pfx/host/chain.hpp>

namespace pfx::bench {

struct ShiftFigures {
  double energy_cv = 0;
  double shape_rms = 0;
};

// depth: the frame's depth texture (0 without). False with *error when a render fails.
bool measure_shift(pfx::host::Chain& chain, pfx_frame frame, uint32_t depth, ShiftFigures* out, std::string* error);

}  // namespace pfx::bench
