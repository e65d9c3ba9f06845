// pfx-validate: checks plugins before they ship (docs/reliability.md). Exit codes in
// validate_usage().
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "report.hpp"
#include "validate_options.hpp"
#include "validation.hpp"

using namespace pfx::validate;
using namespace pfx::exit_code;

int main(int argc, char** argv) {
  ValidateOptions options;
  std::string error;
  if (!parse_validate_options(std::vector<std::string>(argv + 1, argv + argc), &options, &error)) {
    std::fprintf(stderr, "pfx-validate: %s\n\n%s", error.c_str(), validate_usage().c_str());
    return kUsage;
  }
  if (options.help) {
    std::fputs(validate_usage().c_str(), stdout);
    return kOk;
  }
  std::vector<std::string> files;
  if (!expand_plugin_paths(options.paths, &files, &error)) {
    std::fprintf(stderr, "pfx-validate: %s\n", error.c_str());
    return kUsage;
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
      if (!result.passed()) return kCheckFailed;
    return kOk;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pfx-validate: internal error: %s\n", e.what());
    return kInternal;
  }
}
