// Running jobs on a few threads: the calling thread works too (as worker 0), so one thread means
// no thread is started at all. An exception in any job is rethrown on the calling thread after
// every worker has stopped.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <memory>
#include <vector>

#include "obj_helper_thread.hpp"

namespace pfx_obj {

// Calls job(index, worker) once for every index in [0, count), on `threads` workers; the indices
// are handed out in increasing order. `after_own_job` (optional) runs on the calling thread after
// each job it finished, for progress reports.
inline void run_parallel(unsigned threads, size_t count, const std::function<void(size_t, unsigned)>& job,
                         const std::function<void()>& after_own_job = nullptr) {
  if (threads < 1) threads = 1;
  if (threads > count) threads = static_cast<unsigned>(count > 0 ? count : 1);
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&](unsigned worker) {
    for (;;) {
      size_t index = next.fetch_add(1);
      if (index >= count || stop.load()) return;
      try {
        job(index, worker);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
        return;
      }
      if (worker == 0 && after_own_job) after_own_job();
    }
  };
  {
    const WorkerPlacement placement(threads);  // pins the calling thread for the run, where it pins
    std::vector<std::unique_ptr<HelperThread>> helpers;
    for (unsigned w = 1; w < threads; ++w)
      helpers.push_back(std::make_unique<HelperThread>(placement, w, [&work, w] { work(w); }));
    work(0);
  }  // the helpers are joined here, then the caller's affinity restored
  if (failure) std::rethrow_exception(failure);
}

// Calls part(worker) once for each of `threads` workers: for work split by ownership (each
// worker handles the items it owns) rather than by job.
inline void run_on_each_worker(unsigned threads, const std::function<void(unsigned)>& part) {
  run_parallel(threads, threads, [&](size_t index, unsigned) { part(static_cast<unsigned>(index)); });
}

}  // namespace pfx_obj
