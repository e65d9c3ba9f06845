// The thread pool libpfxhost offers its plugins as the service "pfx.thread_pool/1"
// (pfx/services.h), so that a plugin's CPU work (an importer's parsing) runs on threads the host
// owns instead of threads the plugin starts in somebody else's process.
//
// Its threads are plain std::threads, started together the first time a run can use them and
// joined when the pool dies. They change nothing about themselves: they keep the affinity,
// scheduling and signal mask of the thread that started them, as any thread would. The thread
// that calls run() works too, so a run never waits for a task no thread has taken, and a task may
// call run() again (the nested run shares the pool's threads with everything else running).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include <pfx/services.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

class PFX_HOST_API ThreadPool {
 public:
  // `concurrency`: how many tasks may run at once, the calling thread included, so the pool owns
  // concurrency - 1 threads. 0: std::thread::hardware_concurrency() (1 where that is unknown).
  explicit ThreadPool(unsigned concurrency = 0);
  ~ThreadPool();  // joins the threads; no run may be in progress
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned concurrency() const { return concurrency_; }
  // Runs task(user, i) for every i in [0, count) and returns when all have returned: the
  // contract of pfx_thread_pool.run. Tasks must not throw.
  void run(pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel);
  // Starts the threads now instead of at the first run that can use them (a host that counts
  // its threads, or wants them started at a time of its choosing).
  void start();
  // How many threads the pool has started (0 until the first parallel run or start()).
  unsigned threads_started() const;

  // This pool as the C service, valid as long as the pool.
  const pfx_thread_pool* service() const { return &service_; }

 private:
  struct Job;
  void start_locked();
  void worker_loop();

  const unsigned concurrency_;
  pfx_thread_pool service_{};
  mutable std::mutex mutex_;
  std::condition_variable work_ready_;  // a job was queued, or the pool is stopping
  std::deque<Job*> queue_;              // runs that still want helpers
  std::vector<std::thread> threads_;
  bool stopping_ = false;
};

}  // namespace pfx::host
