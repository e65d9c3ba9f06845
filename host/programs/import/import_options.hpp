// pfx-import's command line.
#pragma once

#include <string>
#include <vector>

namespace pfx::import {

struct ImportOptions {
  bool help = false;
  std::string file;
  bool json = false;
  unsigned threads = 0;  // 0: every hardware thread
  std::string progress = "auto";  // auto (when stderr is a terminal), on, off
  std::vector<std::string> plugin_dirs;
};

bool parse_import_options(const std::vector<std::string>& args, ImportOptions* out, std::string* error);
std::string import_usage();

}  // namespace pfx::import
