// pfx-inject's command line: the settings for libpfxinject.so, the application to start, and
// the --bench run.
#pragma once

#include <string>
#include <vector>

#include "inject_settings.hpp"

namespace pfx::inject {

// pfx-inject's own exit codes. An application's own code passes through unchanged, so these sit
// where applications and shells do not: 0-125 are the application's, 126 and 127 the shell's,
// 128 + N a signal (N up to 64), 255 an exit(-1).
constexpr int kExitUsage = 240;       // a bad option, chain, preset, --set or capture
constexpr int kExitSetup = 241;       // libpfxinject.so or every effect plugin missing
constexpr int kExitNotStarted = 242;  // the application could not be started
constexpr int kExitBench = 243;       // --bench measured nothing, or could not write its results

struct InjectOptions {
  InjectSettings settings;
  std::vector<std::string> command;  // the application and its arguments (after --)
  int bench_frames = 0;              // > 0: --bench, frames per run
  int bench_runs = 3;
  std::string bench_json;
  bool panel = false;                      // --panel: the live control panel beside the application
  std::vector<std::string> panel_options;  // --panel-option ARG: passed on to pfx-view
  bool help = false;
};

bool parse_inject_options(const std::vector<std::string>& args, InjectOptions* out, std::string* error);
std::string inject_usage();

}  // namespace pfx::inject
