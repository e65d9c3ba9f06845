// The injected chain's per-pass times for the live control panel (pfx-view --attach): a small
// JSON file (app_timings.hpp in host/programs/view reads it) replaced whole four times a second, or every
// 16th present if that comes first (so a clock stopped by libfaketime does not stop it).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include <pfx/host/chain.hpp>

namespace pfx::inject {

class TimingsChannel {
 public:
  explicit TimingsChannel(std::string path) : path_(std::move(path)) {}
  bool enabled() const { return !path_.empty(); }
  // After a present: writes `times` (measured in the chain's frame; `frame` is the presented
  // frame's number) when it is time to. False with *error when the file could not be written.
  bool offer(uint64_t frame, const std::string& chain, const host::FrameReport& report, std::string* error);

 private:
  std::string path_;
  std::chrono::steady_clock::time_point next_write_{};
  int presents_since_write_ = 0;
};

}  // namespace pfx::inject
