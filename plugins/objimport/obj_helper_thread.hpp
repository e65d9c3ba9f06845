// Where run_parallel's workers run (obj_parallel.hpp), and the helper threads it starts.
//
// Linux often starts a new thread on its creator's CPU and moves it only later, and the kernel of
// the virtual machines this project is measured on goes further: it packs the threads of a
// process that was idle a moment before onto one vCPU. There, ten 2.5 ms jobs on two threads ran
// on one core for the whole 24 ms in 3 of 5 runs, and a two-thread import of a 10 MB file had its
// helper moved onto the caller's vCPU for milliseconds at a time (two threads took 9.7 ms, median
// of 31 imports, against 9.9 ms on one).
//
// So each worker gets a CPU of the caller's allowed set: the caller (worker 0) the one it runs on,
// helper w the w-th allowed CPU after it. With no more workers than allowed CPUs, every worker is
// pinned to its CPU for the run — the caller's own affinity is restored when the run ends — and
// the 10 MB import took 7.0 ms on two threads (median of 31). With more workers than CPUs, pinning
// would stack workers on CPUs for good: each helper only starts on its CPU and then allows itself
// every CPU of the set again, so the placement is a start and not a pin.
#pragma once

#include <pthread.h>
#include <sched.h>

#include <functional>
#include <vector>

namespace pfx_obj {

// The CPUs of one run, chosen when it starts; pins the calling thread until destroyed when the
// run pins (see above).
class WorkerPlacement {
 public:
  explicit WorkerPlacement(unsigned workers);
  ~WorkerPlacement();  // the caller's affinity restored
  WorkerPlacement(const WorkerPlacement&) = delete;
  WorkerPlacement& operator=(const WorkerPlacement&) = delete;

  // The CPU worker w (1, 2, ...) starts on, or -1 when the caller's CPUs are unknown.
  int cpu_of(unsigned worker) const { return cpus_.empty() ? -1 : cpus_[(here_ + worker) % cpus_.size()]; }
  // Whether workers stay on their CPU for the run.
  bool pinned() const { return pinned_; }
  // The caller's allowed CPUs, which a helper that is not pinned allows itself once started.
  const cpu_set_t& allowed() const { return allowed_; }

 private:
  cpu_set_t allowed_;
  std::vector<int> cpus_;  // the allowed CPUs in increasing order
  size_t here_ = 0;        // the caller's CPU, as an index into cpus_
  bool pinned_ = false;    // the run pins its workers, the caller included
};

class HelperThread {
 public:
  // Runs body() on a new thread: worker `index` (1, 2, ...) of `placement`. Throws
  // std::system_error when no thread can be started.
  HelperThread(const WorkerPlacement& placement, unsigned index, std::function<void()> body);
  ~HelperThread();  // joins
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

 private:
  static void* start(void* self);

  std::function<void()> body_;
  const cpu_set_t* allow_after_start_ = nullptr;  // the set a helper not pinned moves to once started
  pthread_t thread_{};
};

}  // namespace pfx_obj
