#include "timings_channel.hpp"

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"

namespace pfx::inject {
namespace {

constexpr std::chrono::milliseconds kWriteInterval{250};
constexpr int kPresentsBetweenWrites = 16;

}  // namespace

bool TimingsChannel::offer(uint64_t frame, const std::string& chain, const host::FrameReport& report,
                           std::string* error) {
  if (path_.empty() || report.times.frame == 0) return true;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_write_ && ++presents_since_write_ < kPresentsBetweenWrites) return true;
  next_write_ = now + kWriteInterval;
  presents_since_write_ = 0;
  nlohmann::ordered_json root;
  root["frame"] = frame;
  root["timing"] = report.timing;
  root["chain"] = chain;
  root["total_ms"] = report.times.total_ms;
  root["passes"] = nlohmann::json::array();
  for (const auto& pass : report.times.passes)
    root["passes"].push_back({{"effect", pass.effect}, {"pass", pass.pass}, {"ms", pass.ms}});
  return app::write_text_atomically(path_, root.dump() + "\n", error);
}

}  // namespace pfx::inject
