#include "frame_timer.hpp"

#include <utility>

namespace pfx::host {

FrameTimer::FrameTimer(Timing timing, GpuTimer& gpu, uint64_t frame) : timing_(timing), gpu_(gpu), frame_(frame) {
  if (timing_ == Timing::GPU_QUERIES) gpu_.begin_frame(frame_);
  if (timing_ == Timing::FINISH_AND_CLOCK) glFinish();
}

FrameTimer::~FrameTimer() {
  if (!finished_) gpu_.abandon_frame();
}

void FrameTimer::start_pass() {
  if (timing_ == Timing::FINISH_AND_CLOCK) pass_start_ = Clock::now();
}

void FrameTimer::end_pass(const std::string& effect, const std::string& pass) {
  if (timing_ == Timing::GPU_QUERIES) gpu_.end_pass(effect, pass);
  if (timing_ == Timing::FINISH_AND_CLOCK) {
    glFinish();
    clock_ms_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - pass_start_).count());
  }
}

bool FrameTimer::finish(std::vector<PassTime>* passes, FrameTimes* times) {
  finished_ = true;
  if (timing_ == Timing::GPU_QUERIES) {
    gpu_.end_frame();
    // Earlier frames only, and only those whose queries have landed: never a wait.
    return gpu_.poll(frame_, times);
  }
  if (timing_ != Timing::FINISH_AND_CLOCK) return false;
  FrameTimes measured;
  measured.frame = frame_;
  for (size_t i = 0; i < passes->size(); ++i) {
    (*passes)[i].ms = clock_ms_[i];
    measured.total_ms += clock_ms_[i];
  }
  measured.passes = *passes;
  *times = std::move(measured);
  return true;
}

}  // namespace pfx::host
