// pfx-inject --panel: the live control panel beside the application. The application is touched
// no more than by a preset file: the launcher writes a session preset (the --preset file's look,
// with --chain and --set applied) into a folder of its own, points the library at it and at a
// timings file there, and starts pfx-view --attach on both. pfx-view writes every change to the
// session preset, which the library applies within a second; its own "save" and "load" use the
// --preset file (default pfx-preset.json). The panel ends with the application; closing the panel
// leaves the application running.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "inject_options.hpp"

namespace pfx::inject {

struct PanelSession {
  std::string folder, preset, timings;
  std::string user_preset;  // what "save preset" and "load preset" use
  pid_t pid = -1;           // pfx-view, once started
};

// Creates the folder and the session preset and rewrites options->settings so the library
// watches it (its chain and values now live there, so --chain and --set are not passed on).
// False with *error.
bool prepare_panel(InjectOptions* options, PanelSession* session, std::string* error);
// Starts pfx-view --attach (not waited for). False with *error when it could not be started.
bool start_panel(const InjectOptions& options, PanelSession* session, std::string* error);
// Closes the panel (SIGTERM, then waits for it) and removes the session folder.
void end_panel(PanelSession* session);

}  // namespace pfx::inject
