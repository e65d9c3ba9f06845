// What pfx-inject checks before it starts the application, so that a mistake on its command line
// is said at once, with a usage error, instead of in the log of an application already running:
// the plugins load, every effect of the chain exists, the preset reads and its values apply,
// every --set names an effect, a parameter and a value that fit, and every capture can be written.
#pragma once

#include <string>
#include <vector>

#include "inject_options.hpp"

namespace pfx::inject {

struct LaunchCheck {
  int exit_code = 0;                // 0, exit_code::kInjectUsage or exit_code::kInjectSetup
  std::vector<std::string> errors;  // one line each, naming the option
  std::vector<std::string> notes;   // values the parameter store adjusted (clamped), not errors
};

LaunchCheck check_launch(const InjectOptions& options);

}  // namespace pfx::inject
