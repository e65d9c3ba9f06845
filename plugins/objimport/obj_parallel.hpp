// Running jobs on the host's thread pool (pfx/services.h): the importer starts no thread of its own
// and leaves every thread's affinity, priority and signal mask alone — the host decides those.
// Without a pool, or with one worker, the jobs run in order on the calling thread. An exception in
// any job is rethrown on the calling thread once every worker has stopped.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include <pfx/services.h>

namespace pfx_obj {

// Calls job(index, worker) once for every index in [0, count), on at most `threads` workers at
// once: each worker is one task of a pool run and takes indices in increasing order until none is
// left, so no task waits for another. `worker` (0 to threads - 1) names scratch memory of the
// worker's own; one worker index never runs twice at once. `after_own_job` (optional) runs on the
// calling thread after each job it finished there, for progress reports.
inline void run_parallel(const pfx_thread_pool* pool, unsigned threads, size_t count,
                         const std::function<void(size_t, unsigned)>& job,
                         const std::function<void()>& after_own_job = nullptr) {
  if (threads < 1) threads = 1;
  if (threads > count) threads = static_cast<unsigned>(count > 0 ? count : 1);
  if (!pool || threads == 1) {
    for (size_t index = 0; index < count; ++index) {
      job(index, 0);
      if (after_own_job) after_own_job();
    }
    return;
  }
  struct Run {
    Run(const std::function<void(size_t, unsigned)>& job, const std::function<void()>& after_own_job, size_t count)
        : job(job), after_own_job(after_own_job), count(count) {}
    const std::function<void(size_t, unsigned)>& job;
    const std::function<void()>& after_own_job;
    size_t count;
    std::thread::id caller = std::this_thread::get_id();
    std::atomic<size_t> next{0};
    std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
  } run(job, after_own_job, count);
  auto work = [](void* user, uint32_t worker) {
    Run& r = *static_cast<Run*>(user);
    const bool on_caller = std::this_thread::get_id() == r.caller;
    for (;;) {
      const size_t index = r.next.fetch_add(1);
      if (index >= r.count || r.stop.load()) return;
      try {
        r.job(index, worker);
        if (on_caller && r.after_own_job) r.after_own_job();
      } catch (...) {  // a pool task must not throw: the caller rethrows it
        std::lock_guard<std::mutex> lock(r.failure_mutex);
        if (!r.failure) r.failure = std::current_exception();
        r.stop = true;
        return;
      }
    }
  };
  pool->run(pool->pool_data, work, &run, threads, threads);
  if (run.failure) std::rethrow_exception(run.failure);
}

// Calls part(worker) once for each of `threads` workers: for work split by ownership (each
// worker handles the items it owns) rather than by job.
inline void run_on_each_worker(const pfx_thread_pool* pool, unsigned threads, const std::function<void(unsigned)>& part) {
  run_parallel(pool, threads, threads, [&](size_t index, unsigned) { part(static_cast<unsigned>(index)); });
}

}  // namespace pfx_obj
