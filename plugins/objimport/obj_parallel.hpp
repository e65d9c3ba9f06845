// Running jobs on the host's thread pool (pfx/services.h): the importer starts no thread of its own
// and leaves every thread's affinity, priority and signal mask alone — the host decides those.
// Without a pool, or with one worker, the jobs run in order on the calling thread. An exception in
// a job stops the run and is rethrown on the calling thread once every worker has stopped.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include <pfx/services.h>

namespace pfx_obj {

// Calls work(worker) once for each of `threads` workers: the tasks of one pool run, which the pool
// may run one after another, or in turn on the calling thread. On a pool, `work` must not throw (it
// runs behind the pool's C interface); run_ordered_jobs catches for its jobs.
inline void run_workers(const pfx_thread_pool* pool, unsigned threads, const std::function<void(unsigned)>& work) {
  if (!pool || threads <= 1) {
    for (unsigned worker = 0; worker < std::max(1u, threads); ++worker) work(worker);
    return;
  }
  auto task = [](void* user, uint32_t worker) noexcept { (*static_cast<const std::function<void(unsigned)>*>(user))(worker); };
  pool->run(pool->pool_data, task, const_cast<std::function<void(unsigned)>*>(&work), threads, threads);
}

// Two jobs per item on a few workers: the first for any item on any worker at once (reading a
// chunk), the second strictly in item order, one at a time, after the item's first (numbering it);
// `in_order` null: none. A worker takes the next in-order job whenever it is ready, else the next
// first job. At most `window` consecutive items are between their first job's start and their
// in-order job's end, so item % window names working memory no other item in flight uses. A
// worker waits only while another runs a job (when none runs, one of the two is ready), so a pool
// that runs its tasks one after another still finishes. `worker` (below `threads`) names scratch
// memory of the worker's own.
inline void run_ordered_jobs(const pfx_thread_pool* pool, unsigned threads, size_t count, size_t window,
                             const std::function<void(size_t item, unsigned worker)>& first,
                             const std::function<void(size_t item)>& in_order) {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<char> first_done(count, 0);
  size_t next_first = 0, next_in_order = 0;
  bool in_order_running = false, stop = false;
  std::exception_ptr failure;
  run_workers(pool, threads, [&](unsigned worker) {
    std::unique_lock<std::mutex> lock(mutex);
    while (!stop && next_in_order < count) {
      const bool ordered = !in_order_running && first_done[next_in_order];
      if (!ordered && !(next_first < count && next_first < next_in_order + std::max<size_t>(window, 1))) {
        changed.wait(lock);
        continue;
      }
      const size_t item = ordered ? next_in_order : next_first++;
      in_order_running |= ordered;
      lock.unlock();
      std::exception_ptr thrown;
      try {
        if (!ordered) first(item, worker);
        else if (in_order) in_order(item);
      } catch (...) {
        thrown = std::current_exception();
      }
      lock.lock();
      if (thrown && !failure) failure = thrown;
      in_order_running &= !ordered;
      if (ordered) ++next_in_order;
      else first_done[item] = 1;
      stop = stop || thrown;
      changed.notify_all();
    }
  });
  if (failure) std::rethrow_exception(failure);
}

// job(index, worker) once for every index in [0, count).
inline void run_parallel(const pfx_thread_pool* pool, unsigned threads, size_t count,
                         const std::function<void(size_t, unsigned)>& job) {
  run_ordered_jobs(pool, threads, count, count, job, nullptr);
}

}  // namespace pfx_obj
