// pfx-bench --import: the OBJ importer against tinyobjloader and assimp (Debian packages, linked
// by the benchmark only), in one run, on OBJ files generated in several layouts at given sizes: MB/s
// and peak memory,
// our importer at each thread count. Every load runs in a new process (import_measure.hpp), so one
// loader's heap and peak never count against the next.
#pragma once

#include <string>
#include <vector>

#include "import_files.hpp"

namespace pfx::bench {

struct ImportBenchOptions {
  bool help = false;
  std::vector<double> sizes_mb = {100, 500};
  std::vector<ObjLayout> layouts = all_layouts();
  std::vector<unsigned> threads = {1, 2};
  std::vector<std::string> loaders = {"pfx", "tinyobjloader", "assimp"};
  int runs = 5;                  // loads per row, in rounds of one load per row
  std::string work_dir;          // where the generated files go (default: a fresh folder in /tmp)
  bool keep_files = false;
  std::string out_dir = "out/bench";
  std::vector<std::string> plugin_dirs;
};

bool parse_import_bench_options(const std::vector<std::string>& args, ImportBenchOptions* out, std::string* error);
std::string import_bench_usage();

// Runs the whole benchmark; returns the process exit code.
int import_bench_main(const std::vector<std::string>& args);

}  // namespace pfx::bench
