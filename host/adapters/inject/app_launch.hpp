// Starting the application with libpfxinject.so preloaded and the settings in its environment.
#pragma once

#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

// Where libpfxinject.so is beside this program (bin/../lib in a build tree or an install); empty
// with *error when it is missing.
std::string find_inject_library(std::string* error);
// The plugin folders the library will search: --plugins, else the one beside this program.
std::vector<std::string> plugin_folders(const InjectSettings& settings);
// The child's environment: ours without inherited PFX_INJECT_* variables, plus `settings`, and
// `library` first in LD_PRELOAD (anything already preloaded, libfaketime say, stays after it).
std::vector<std::string> child_environment(const InjectSettings& settings, const std::string& library);
// Runs command[0] (looked up in PATH) with the arguments and environment; waits for it. Returns
// its exit code, 128 + the signal that ended it, or exit_code::kInjectNotStarted with *error
// when it could not start.
int run_application(const std::vector<std::string>& command, const std::vector<std::string>& environment,
                    std::string* error);

}  // namespace pfx::inject
