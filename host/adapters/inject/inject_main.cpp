// pfx-inject: runs a pfx chain inside an existing OpenGL application (docs/inject.md).
#include <cstdio>
#include <string>
#include <vector>

#include "app_launch.hpp"
#include "inject_bench.hpp"
#include "inject_options.hpp"
#include "launch_check.hpp"
#include "panel_launch.hpp"

using namespace pfx::inject;

int main(int argc, char** argv) {
  InjectOptions options;
  std::string error;
  if (!parse_inject_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-inject: %s\n\n%s", error.c_str(), inject_usage().c_str());
    return pfx::exit_code::kInjectUsage;
  }
  if (options.help) {
    std::fputs(inject_usage().c_str(), stdout);
    return 0;
  }
  // Everything the library would only find at the application's first present is checked here,
  // before the application starts.
  const LaunchCheck check = check_launch(options);
  for (const auto& note : check.notes) std::fprintf(stderr, "pfx-inject: %s\n", note.c_str());
  for (const auto& problem : check.errors) std::fprintf(stderr, "pfx-inject: %s\n", problem.c_str());
  if (check.exit_code) {
    if (check.exit_code == pfx::exit_code::kInjectUsage) std::fprintf(stderr, "pfx-inject: the application was not started\n");
    return check.exit_code;
  }
  const std::string library = find_inject_library(&error);
  if (library.empty()) {
    std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
    return pfx::exit_code::kInjectSetup;
  }
  if (options.bench_frames) return run_bench(options, library);
  PanelSession panel;
  if (options.panel && (!prepare_panel(&options, &panel, &error) || !start_panel(options, &panel, &error))) {
    std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
    end_panel(&panel);
    return pfx::exit_code::kInjectSetup;
  }
  const int code = run_application(options.command, child_environment(options.settings, library), &error);
  if (!error.empty()) std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
  if (options.panel) end_panel(&panel);
  return code;
}
