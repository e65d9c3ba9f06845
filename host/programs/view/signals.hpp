// Signals a running viewer answers, so scripts and tests can drive it: SIGUSR1 takes a screenshot
// (as F12 does), SIGINT and SIGTERM close the window cleanly. The handlers only set flags; the
// main loop acts on them between frames.
#pragma once

namespace pfx::app {

void install_viewer_signal_handlers();
// Each returns true once per signal received (the flag is cleared).
bool screenshot_signalled();
bool quit_signalled();

}  // namespace pfx::app
