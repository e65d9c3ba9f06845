#include "present_stats.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"

namespace pfx::inject {

void PresentStats::presented() { stamps_.push_back(std::chrono::steady_clock::now()); }

double PresentStats::median_frame_ms(size_t warm_up) const {
  std::vector<double> intervals;
  for (size_t i = std::max<size_t>(warm_up, 1); i < stamps_.size(); ++i)
    intervals.push_back(std::chrono::duration<double, std::milli>(stamps_[i] - stamps_[i - 1]).count());
  if (intervals.empty()) return 0;
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  return intervals[intervals.size() / 2];
}

bool PresentStats::write(const std::string& path, double copy_pass_ms, const std::string& mode,
                         const std::string& chain, std::string* error) const {
  nlohmann::ordered_json root;
  root["mode"] = mode;
  root["chain"] = chain;
  root["frames"] = stamps_.size();
  root["frames_through_chain"] = ran_chain_;
  // A tenth of the frames (at least two) warm caches and the JIT before the median counts.
  root["frame_ms"] = median_frame_ms(std::max<size_t>(2, stamps_.size() / 10));
  root["copy_pass_ms"] = copy_pass_ms;
  return app::write_text_atomically(path, root.dump(2) + "\n", error);
}

}  // namespace pfx::inject
