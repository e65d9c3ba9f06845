// Times one render()'s passes under the chain's timing scheme, so that running the passes reads
// the same whichever scheme is chosen: start_pass / end_pass around each pass, finish when every
// pass ran. A frame that fails part way (the timer is destroyed unfinished) leaves no half-stamped
// query set in flight.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu_timer.hpp"
#include "pfx/host/timing.hpp"

namespace pfx::host {

class FrameTimer {
 public:
  // GPU_QUERIES stamps the frame's start; FINISH_AND_CLOCK waits for the GPU to be idle.
  FrameTimer(Timing timing, GpuTimer& gpu, uint64_t frame);
  ~FrameTimer();
  FrameTimer(const FrameTimer&) = delete;
  FrameTimer& operator=(const FrameTimer&) = delete;

  // Just before the plugin's run_pass.
  void start_pass();
  // As soon as the pass (and the pass hook after it) returned: stamps its end on the GPU, or
  // waits for it and reads the clock. `effect` is the instance's name ("bloom#2").
  void end_pass(const std::string& effect, const std::string& pass);
  // Every pass ran. FINISH_AND_CLOCK: fills in the times of `passes` (the frame's, in order) and
  // makes *times this frame's. GPU_QUERIES: the frame joins those in flight and *times becomes
  // the newest earlier frame whose queries have landed, if any did (never a wait). True when
  // *times changed.
  bool finish(std::vector<PassTime>* passes, FrameTimes* times);

 private:
  using Clock = std::chrono::steady_clock;
  Timing timing_;
  GpuTimer& gpu_;
  uint64_t frame_;
  bool finished_ = false;
  Clock::time_point pass_start_;
  std::vector<double> clock_ms_;  // FINISH_AND_CLOCK: per pass, in order
};

}  // namespace pfx::host
