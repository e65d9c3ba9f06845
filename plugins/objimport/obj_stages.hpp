// Timing the import's stages, for the benchmark's breakdown (ObjMesh::stages): each stage's wall
// time and the CPU time of all the process's threads during it, and whether it runs on every
// thread or on one — what limits the speed-up from more threads.
#pragma once

#include <time.h>

#include <chrono>
#include <cstring>
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

  // Runs work() and adds its times to the stage `name` (a stage timed again, as the one-thread
  // import times each chunk's parse, adds up).
  template <typename Work>
  void time(const char* name, bool parallel, Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    work();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = process_cpu_seconds() - cpu_start;
    for (ImportStage& stage : *out_)
      if (std::strcmp(stage.name, name) == 0) {
        stage.seconds += seconds;
        stage.cpu_seconds += cpu;
        return;
      }
    out_->push_back({name, parallel, seconds, cpu});
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
