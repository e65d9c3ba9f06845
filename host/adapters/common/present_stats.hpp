// Frame times at the present call, for pfx-inject --bench: the interval between one present's
// return and the next's, which is the application's whole frame, our work included.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace pfx::inject {

class PresentStats {
 public:
  void presented();
  // A present whose frame went through the chain (copied in, passes run, copied out); the others
  // were presented as the application drew them.
  void ran_chain() { ++ran_chain_; }
  // Median interval in milliseconds, leaving out the first `warm_up` frames; 0 with too few.
  double median_frame_ms(size_t warm_up) const;
  size_t frames() const { return stamps_.size(); }
  // Writes {"mode", "chain", "frames", "frames_through_chain", "frame_ms", "copy_pass_ms"} as
  // JSON, atomically.
  bool write(const std::string& path, double copy_pass_ms, const std::string& mode, const std::string& chain,
             std::string* error) const;

 private:
  std::vector<std::chrono::steady_clock::time_point> stamps_;
  size_t ran_chain_ = 0;
};

}  // namespace pfx::inject
