// pfx-validate: checks plugins before they ship (docs/reliability.md). Exit codes in
// validate_usage().
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "report.hpp"
#include "validate_options.hpp"
#include "validation.hpp"

using namespace pfx::validate;

int main(int argc, char** argv) {
  ValidateOptions options;
  std::string error;
  if (!parse_validate_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-validate: %s\n\n%s", error.c_str(), validate_usage().c_str());
    return 2;
  }
  if (options.help) {
    std::fputs(validate_usage().c_str(), stdout);
    return 0;
  }
  std::vector<std::string> files;
  if (!expand_plugin_paths(options.paths, &files, &error)) {
    std::fprintf(stderr, "pfx-validate: %s\n", error.c_str());
    return 2;
  }
  try {
    ValidationSettings settings;
    settings.seed = options.seed;
    settings.runs = options.runs;
    settings.timeout_s = options.timeout_s;
    std::vector<PluginResult> results;
    for (const std::string& file : files) results.push_back(validate_plugin(file, settings));
    check_unique_ids(&results);
    std::fputs((options.json ? report_json(results, settings) : report_text(results, settings)).c_str(), stdout);
    for (const PluginResult& result : results)
      if (!result.passed()) return 1;
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pfx-validate: internal error: %s\n", e.what());
    return 1;
  }
}
