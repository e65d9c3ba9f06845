// pfx-inject: runs a pfx chain inside an existing OpenGL application (docs/inject.md).
#include <cstdio>
#include <string>
#include <vector>

#include "app_launch.hpp"
#include "inject_bench.hpp"
#include "inject_options.hpp"
#include "preset.hpp"

using namespace pfx::inject;

int main(int argc, char** argv) {
  InjectOptions options;
  std::string error;
  if (!parse_inject_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-inject: %s\n\n%s", error.c_str(), inject_usage().c_str());
    return 2;
  }
  if (options.help) {
    std::fputs(inject_usage().c_str(), stdout);
    return 0;
  }
  // A preset that does not read is a mistake of the command line: say so before the application
  // starts rather than in its log.
  pfx::app::Preset preset;
  if (!options.settings.preset.empty() && !pfx::app::read_preset(options.settings.preset, &preset, &error)) {
    std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
    return 2;
  }
  const std::string library = find_inject_library(&error);
  if (library.empty()) {
    std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
    return 1;
  }
  if (options.bench_frames) return run_bench(options, library);
  const int code = run_application(options.command, child_environment(options.settings, library), &error);
  if (!error.empty()) std::fprintf(stderr, "pfx-inject: %s\n", error.c_str());
  return code;
}
