// pfx-validate's command line, parsed into plain data so it can be tested and fuzzed on its own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfx::validate {

struct ValidateOptions {
  bool help = false;
  bool json = false;
  std::vector<std::string> paths;  // plugin files, or folders meaning every *.so in them
  uint64_t seed = 1;
  int runs = 8;
  double timeout_s = 120;
};

// Parses argv (without argv[0]). False with *error for a usage error (exit code 2).
bool parse_validate_options(const std::vector<std::string>& args, ValidateOptions* out, std::string* error);
std::string validate_usage();

// Files stay as given; a folder becomes its *.so files in name order. False with *error when a
// path does not exist or a folder holds no plugin.
bool expand_plugin_paths(const std::vector<std::string>& paths, std::vector<std::string>* files, std::string* error);

}  // namespace pfx::validate
