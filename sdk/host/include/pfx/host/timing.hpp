// How a chain times its passes, and the times it reports: below both the Chain (which reports
// them) and the GPU timer inside libpfxhost (which measures them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfx::host {

// How render() times passes; the embedding program chooses (Chain::set_timing), libpfxhost never
// guesses from the renderer.
enum class Timing {
  // No queries, no waiting, no times (the default).
  OFF,
  // A GL timestamp query around every pass, read back one or more frames later without waiting:
  // report().times holds the newest frame whose queries have landed.
  GPU_QUERIES,
  // glFinish before and after every pass and a CPU clock: serialises the GPU, but measures what a
  // deferred software renderer (Mesa's llvmpipe, whose timestamps are taken when commands are
  // queued, not when they run) really spends on each pass. The times are this frame's.
  FINISH_AND_CLOCK
};

// Effects are named by instance, as the parameter store names them: "bloom" for the first
// instance of an effect in the chain, "bloom#2" for the second.
struct PassTime {
  std::string effect, pass;
  double ms = 0;
};

// The times of one frame's passes.
struct FrameTimes {
  uint64_t frame = 0;            // the FrameReport::frame they were measured in; 0: none yet
  std::vector<PassTime> passes;  // that frame's passes, in order, with their times
  double total_ms = 0;
};

}  // namespace pfx::host
