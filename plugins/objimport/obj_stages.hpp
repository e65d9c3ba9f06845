// Timing the import's stages, for the benchmark's breakdown (ObjMesh::stages): each stage's wall
// time and the CPU time of all the process's threads during it, and whether it runs on every
// thread or on one — what limits the speed-up from more threads.
#pragma once

#include <time.h>

#include <chrono>
#include <vector>

namespace pfx_obj {

struct ImportStage {
  const char* name;
  bool parallel;  // runs on every thread (false: on the calling thread alone)
  double seconds, cpu_seconds;
};

class StageClock {
 public:
  explicit StageClock(std::vector<ImportStage>* out) : out_(out) {}

  template <typename Work>
  void time(const char* name, bool parallel, Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    work();
    out_->push_back({name, parallel, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                     process_cpu_seconds() - cpu_start});
  }

 private:
  static double process_cpu_seconds() {
    timespec now{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
  }

  std::vector<ImportStage>* out_;
};

}  // namespace pfx_obj
