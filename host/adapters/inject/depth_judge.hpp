// Whether an application's depth buffer can be trusted, judged from a grid of its values read at a
// present. Many applications leave nothing useful there: one value everywhere (depth cleared after
// the scene, or the scene drawn into a framebuffer of the application's own and only colour copied
// to the window, as glmark2's terrain does), or reversed-Z, which reads as depth of field focused
// the wrong way round. Effects that need depth are only given a depth buffer judged usable.
#pragma once

#include <cstddef>
#include <string>

namespace pfx::inject {

struct DepthFinding {
  enum Kind { NO_VALUES, ONE_VALUE, REVERSED, USABLE } kind = NO_VALUES;
  std::string what;  // what was found, for the log: "one value everywhere (1: the far plane, ...)"
  bool usable() const { return kind == USABLE; }
};

// `samples` are window-space depth values (0 near, 1 far, as the application's projection wrote
// them). Non-finite ones count as not drawn.
DepthFinding judge_depth(const float* samples, size_t count);

}  // namespace pfx::inject
