// pfx-bench's command line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pfx::bench {

struct BenchOptions {
  bool help = false;
  std::vector<std::string> plugin_dirs;
  std::string out_dir = "out/bench";
  std::vector<std::pair<int, int>> sizes = {{1280, 720}, {1920, 1080}};
  int frames = 15, warmup = 3;
  std::vector<std::string> effects;  // empty: every loaded effect
  std::string suite_file;            // empty: the built-in suite
  bool quick = false;
  std::string timing = "auto";
};

bool parse_bench_options(const std::vector<std::string>& args, BenchOptions* out, std::string* error);
std::string bench_usage();

}  // namespace pfx::bench
