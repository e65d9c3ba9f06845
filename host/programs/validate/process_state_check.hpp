// The "process state" check: every call a host makes into the plugin — loading the library, init,
// create, declare and the passes, destroy, import and release for each importer, deinit and
// unloading — leaves the process and the calling thread as they were (process_state.hpp), and no
// thread running. Runs in its own child process like every check (child_process.hpp).
#pragma once

#include <string>

#include "child_process.hpp"

namespace pfx::validate {

void check_process_state(const std::string& path, CheckReporter& report);

}  // namespace pfx::validate
