#include "timing_choice.hpp"

namespace pfx::app {

pfx::host::Timing default_timing(const std::string& gl_renderer) {
  const bool software =
      gl_renderer.find("llvmpipe") != std::string::npos || gl_renderer.find("softpipe") != std::string::npos;
  return software ? pfx::host::Timing::FINISH_AND_CLOCK : pfx::host::Timing::GPU_QUERIES;
}

bool parse_timing(const std::string& name, const std::string& gl_renderer, pfx::host::Timing* timing) {
  if (name == "auto") *timing = default_timing(gl_renderer);
  else if (name == "gpu") *timing = pfx::host::Timing::GPU_QUERIES;
  else if (name == "finish") *timing = pfx::host::Timing::FINISH_AND_CLOCK;
  else if (name == "off") *timing = pfx::host::Timing::OFF;
  else return false;
  return true;
}

}  // namespace pfx::app
