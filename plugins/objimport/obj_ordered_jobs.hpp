// Two jobs per item on a few workers: the first for any item on any worker at once (parsing a
// chunk), the second strictly in item order, one at a time, each after the item's first job
// (numbering the chunk's corners against one numbering for the whole file). A worker takes the
// next in-order job whenever it is ready — it is the one that holds up the rest — and otherwise
// the next first job, so one worker numbers while the others parse ahead. At most `window` items
// are between their first job's start and their in-order job's end, and those are consecutive, so
// item % window names a slot of working memory no other item in flight uses.
//
// The workers are tasks of one pool run (obj_parallel.hpp), which the pool may run one after
// another on one thread. So a worker waits only for a job another worker is in the middle of,
// never for a worker to start: when no job is running, the next in-order job is ready (its first
// job has finished) or the next first job is (the window has room), and a worker that finds
// neither while no job runs would be a fault in this file, reported as one rather than waited on.
// On one thread the first worker runs first(0), in_order(0), first(1), ... and the others find
// nothing left.
// An in-order job returning false stops the run: no job starts after it. An exception in any job
// stops the run too, and is rethrown on the calling thread once every worker has stopped.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "obj_parallel.hpp"

namespace pfx_obj {

inline void run_ordered_jobs(const pfx_thread_pool* pool, unsigned threads, size_t count, size_t window,
                             const std::function<void(size_t item, unsigned worker)>& first,
                             const std::function<bool(size_t item)>& in_order,
                             const std::function<void()>& after_own_job = nullptr) {
  if (window < 1) window = 1;
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<char> first_done(count, 0);
  size_t next_first = 0, next_in_order = 0;
  bool in_order_running = false, stop = false;
  unsigned running = 0;  // jobs in progress
  std::exception_ptr failure;
  const std::thread::id caller = std::this_thread::get_id();

  auto work = [&](unsigned worker) {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      if (stop || next_in_order == count) return;
      const bool in_order_ready = !in_order_running && first_done[next_in_order];
      const bool first_ready = next_first < count && next_first < next_in_order + window;
      if (!in_order_ready && !first_ready) {
        if (running == 0) {  // see above: cannot happen, and waiting would never end
          if (!failure) failure = std::make_exception_ptr(std::logic_error("ordered jobs: nothing ready, nothing running"));
          stop = true;
          changed.notify_all();
          return;
        }
        changed.wait(lock);
        continue;
      }
      const size_t item = in_order_ready ? next_in_order : next_first++;
      if (in_order_ready) in_order_running = true;
      ++running;
      lock.unlock();
      bool go = true;
      try {
        if (in_order_ready) go = in_order(item);
        else first(item, worker);
      } catch (...) {
        go = false;
        lock.lock();
        if (!failure) failure = std::current_exception();
        lock.unlock();
      }
      if (after_own_job && std::this_thread::get_id() == caller) after_own_job();
      lock.lock();
      --running;
      if (in_order_ready) {
        in_order_running = false;
        ++next_in_order;
      } else {
        first_done[item] = 1;
      }
      if (!go) stop = true;
      changed.notify_all();
    }
  };
  run_on_each_worker(pool, threads, work);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace pfx_obj
