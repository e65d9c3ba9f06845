// pfx-view --attach: the live control panel of a chain injected into a running application. No
// picture of its own: the chain and parameter panels edit the preset the injected library
// watches (written whole whenever something changed), and the application's per-pass times are
// read from the file the library writes. Scripted with --frames and --edit for the tests.
#pragma once

#include "view_options.hpp"

namespace pfx::app {

// The exit code: 0, or as pfx-view's (1 no window, 3 bad preset, 4 plugin or effect error).
int run_attached(const ViewOptions& options);

}  // namespace pfx::app
