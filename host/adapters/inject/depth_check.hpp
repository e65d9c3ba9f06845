// When the pipeline looks at the application's depth buffer and what it concludes: at the first
// frame (waiting once for the answer, so no frame runs on depth it has not checked), then every
// 30th frame and after a resize without waiting (the reading lands a frame or two later), so an
// application that starts drawing depth, or stops, is followed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "depth_judge.hpp"
#include "depth_probe.hpp"

namespace pfx::inject {

class DepthCheck {
 public:
  bool create(std::string* error) { return probe_.create(error); }

  // After the copy in: `depth` is the copy of the default framebuffer's depth (0 when it has none,
  // or it was not copied), width x height its size. Returns whether depth is usable now; when
  // the finding changed, *change holds it for the log.
  bool update(uint64_t frame, GLuint depth, int width, int height, std::optional<DepthFinding>* change);
  // The newest finding; NO_VALUES before the first.
  const DepthFinding& finding() const { return finding_; }

 private:
  DepthProbe probe_;
  DepthFinding finding_;
  bool judged_ = false;
  uint64_t next_look_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::inject
