// Where pfx's OBJ import spends its time: each pipeline stage's wall and CPU time, and whether it
// runs on every thread or on one, at each thread count. Each run is an import in a new process, as
// the loads are (import_measure.hpp), calling the importer's core library (the plugin's own code,
// linked into the benchmark), as the plugin ABI reports only the total. What it shows: how the
// parallel stages scale on their own, and how large the serial part is — the limit on the speed-up
// from more threads, whatever else the machine is doing.
#pragma once

#include <string>
#include <vector>

namespace pfx::bench {

struct StageTime {
  std::string name;
  bool parallel = false;
  double seconds = 0, cpu_seconds = 0;  // medians over the runs
};

struct StageBreakdown {
  bool ok = false;
  std::string error;
  unsigned threads = 1;
  std::vector<StageTime> stages;  // in pipeline order
  double parallel_seconds() const;
  double serial_seconds() const;
};

// Imports `path` `runs` times with `threads` threads, each in a new process; medians per stage.
StageBreakdown measure_stages(const std::string& path, unsigned threads, int runs);

// The loader name that makes `pfx-bench --import-load` print the stages (print_stages).
constexpr const char* kStagesLoader = "pfx-stages";

// In that process: imports `path` once and writes one line per stage on standard output —
// "parallel seconds cpu_seconds name" — or "error MESSAGE". Returns the exit code.
int print_stages(const std::string& path, unsigned threads);

// A markdown section: per file and thread count, the stages; then for each count above one the
// speed-up by wall time and the one its CPU times predict on idle cores (its serial stages' CPU
// time plus its parallel stages' divided by the thread count, against one thread's CPU time).
struct StageTable {
  double file_mb = 0;
  std::vector<StageBreakdown> by_threads;
};
std::string stage_markdown(const std::vector<StageTable>& tables);

}  // namespace pfx::bench
