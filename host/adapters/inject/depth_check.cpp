#include "depth_check.hpp"

#include <vector>

namespace pfx::inject {
namespace {

constexpr uint64_t kFramesBetweenLooks = 30;

}  // namespace

bool DepthCheck::update(uint64_t frame, GLuint depth, int width, int height, std::optional<DepthFinding>* change) {
  change->reset();
  if (!depth) {
    // Nothing to look at: the next depth buffer is judged afresh.
    judged_ = false;
    return false;
  }
  if (width != width_ || height != height_) next_look_ = frame;
  width_ = width;
  height_ = height;
  if (frame >= next_look_ && !probe_.pending()) {
    probe_.start(depth, width, height);
    next_look_ = frame + kFramesBetweenLooks;
  }
  std::vector<float> samples;
  if (probe_.finish(!judged_, &samples)) {
    const DepthFinding finding = judge_depth(samples.data(), samples.size());
    if (!judged_ || finding.kind != finding_.kind) *change = finding;
    finding_ = finding;
    judged_ = true;
  }
  return judged_ && finding_.usable();
}

}  // namespace pfx::inject
