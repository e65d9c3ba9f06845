// A helper thread for run_parallel (obj_parallel.hpp) that starts on a CPU of its own. Linux often
// starts a new thread on its creator's CPU and moves it only later: on the 2-core machines this
// project is measured on, ten 2.5 ms jobs on two threads ran on one core for the whole 24 ms in 3
// of 5 runs, so a short parallel stage gained nothing. So each helper is created already placed
// on a CPU of the caller's allowed set, round-robin from the caller's own; the first thing it does
// is allow itself every CPU of that set again, so the placement is a start and not a pin — a busy
// core does not hold it.
#pragma once

#include <pthread.h>
#include <sched.h>

#include <functional>

namespace pfx_obj {

class HelperThread {
 public:
  // Runs body() on a new thread: helper number `index` (1, 2, ...) of a caller on the CPU it runs
  // on now. Throws std::system_error when no thread can be started.
  HelperThread(unsigned index, std::function<void()> body);
  ~HelperThread();  // joins
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

 private:
  static void* start(void* self);

  std::function<void()> body_;
  cpu_set_t allowed_;
  bool restore_ = false;
  pthread_t thread_{};
};

}  // namespace pfx_obj
