// How pfx-bench times things: medians of frame times, and the plain copy pass every time is
// compared with, timed exactly as the chain times its passes so the ratio compares like with like.
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/host/chain.hpp>

#include "copy_pass.hpp"

namespace pfx::bench {

// The median (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

// One copy of source into target (w x h), in milliseconds: GL timestamps for GPU_QUERIES,
// otherwise glFinish and the CPU clock around it (what AUTO means on a software renderer).
double time_copy(gl::CopyPass& copy, uint32_t source, uint32_t target, int w, int h, pfx::host::Timing timing);

}  // namespace pfx::bench
