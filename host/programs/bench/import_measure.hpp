// One load measured in a process of its own: pfx-bench runs itself again (`--import-load`, below),
// so every load starts in a new process image — nothing inherited from the benchmark's heap, whose
// pages a forked child would first have to copy — and no loader's heap or peak counts against the
// next. Measured there: wall time, CPU time (user + system, all threads: on a shared machine the
// wall time also counts waiting for a core, the CPU time does not), and the peak resident memory
// the load added (VmHWM after the load minus VmRSS before it, with the peak reset first through
// /proc/self/clear_refs). Mapped file pages count, as they are resident. Loading the plugins is not
// timed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "import_loaders.hpp"

namespace pfx::bench {

struct LoadMeasure {
  LoadCounts counts;
  double seconds = 0;
  double cpu_seconds = 0;
  uint64_t peak_bytes = 0;
};

// Runs this program (/proc/self/exe) with `args` (args[0] is the name it sees) and collects its
// standard output and wait status. False when no process could be started.
bool run_self(const std::vector<std::string>& args, std::string* output, int* status);

// Runs `pfx-bench --import-load LOADER FILE THREADS [--plugins DIR]...` and reads its report.
LoadMeasure measure_in_new_process(const std::string& loader, const std::string& path, unsigned threads,
                                   const std::vector<std::string>& plugin_dirs);

// The --import-load mode: loads the plugins, then measures one load and writes the report on
// standard output.
// Returns the exit code (2 on bad arguments).
int import_load_main(const std::vector<std::string>& args);

// Reads the whole file once so every loader finds it in the page cache, and waits until it is on
// disk.
bool warm_file(const std::string& path, std::string* error);

}  // namespace pfx::bench
