// pfx-inject's command line: the settings for libpfxinject.so, the application to start, and
// the --bench run.
#pragma once

#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

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
