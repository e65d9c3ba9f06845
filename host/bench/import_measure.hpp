// One load measured in a forked child: wall time, CPU time (user + system, all threads: on a
// shared machine the wall time also counts waiting for a core, the CPU time does not), and the peak resident memory the load added
// (VmHWM after the load minus VmRSS before it, with the peak reset first through
// /proc/self/clear_refs). Mapped file pages count, as they are resident.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "import_loaders.hpp"

namespace pfx::bench {

struct LoadMeasure {
  LoadCounts counts;
  double seconds = 0;
  double cpu_seconds = 0;
  uint64_t peak_bytes = 0;
};

LoadMeasure measure_in_child(const std::function<LoadCounts()>& load);

// Reads the whole file once so every loader finds it in the page cache, and waits until it is on
// disk.
bool warm_file(const std::string& path, std::string* error);

}  // namespace pfx::bench
