#include "pfx/host/thread_pool.hpp"

#include <algorithm>
#include <atomic>
#include <system_error>

namespace pfx::host {

// One call of run(): its tasks are handed out by `next`, to the caller and to the helpers that
// joined it. It lives on the caller's stack, which run() leaves only once no helper is inside.
struct ThreadPool::Job {
  pfx_task_fn task = nullptr;
  void* user = nullptr;
  uint32_t count = 0;
  std::atomic<uint64_t> next{0};  // 64 bits: every participant overshoots once at the end
  uint32_t helpers_wanted = 0;    // helpers that may still join (under the pool's mutex)
  uint32_t helpers_inside = 0;    // helpers taking tasks now (under the pool's mutex)
  std::condition_variable helpers_left;
};

namespace {

// noexcept: a task that throws ends the process here rather than unwinding past a job that
// other threads still read.
void take_tasks(pfx_task_fn task, void* user, uint32_t count, std::atomic<uint64_t>& next) noexcept {
  for (;;) {
    const uint64_t index = next.fetch_add(1, std::memory_order_relaxed);
    if (index >= count) return;
    task(user, static_cast<uint32_t>(index));
  }
}

unsigned machine_concurrency() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? n : 1;
}

}  // namespace

ThreadPool::ThreadPool(unsigned concurrency) : concurrency_(concurrency > 0 ? concurrency : machine_concurrency()) {
  service_.struct_size = sizeof(pfx_thread_pool);
  service_.pool_data = this;
  service_.concurrency = [](void* pool_data) -> uint32_t { return static_cast<ThreadPool*>(pool_data)->concurrency(); };
  service_.run = [](void* pool_data, pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
    static_cast<ThreadPool*>(pool_data)->run(task, user, count, max_parallel);
  };
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void ThreadPool::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  start_locked();
}

unsigned ThreadPool::threads_started() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<unsigned>(threads_.size());
}

void ThreadPool::start_locked() {
  if (!threads_.empty() || stopping_) return;
  // A thread the system refuses is not an error: the callers of run() do the work themselves.
  try {
    for (unsigned i = 1; i < concurrency_; ++i) threads_.emplace_back([this] { worker_loop(); });
  } catch (const std::system_error&) {
  }
}

void ThreadPool::run(pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
  if (!task || count == 0) return;
  uint32_t at_once = max_parallel > 0 ? std::min<uint32_t>(max_parallel, concurrency_) : concurrency_;
  at_once = std::min(at_once, count);
  Job job;
  job.task = task;
  job.user = user;
  job.count = count;
  if (at_once > 1) {
    job.helpers_wanted = at_once - 1;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      start_locked();
      if (!threads_.empty()) queue_.push_back(&job);
    }
    work_ready_.notify_all();
  }
  take_tasks(task, user, count, job.next);
  // Every task is taken: no helper may join any more, and those inside finish the task they hold.
  std::unique_lock<std::mutex> lock(mutex_);
  const auto queued = std::find(queue_.begin(), queue_.end(), &job);
  if (queued != queue_.end()) queue_.erase(queued);
  job.helpers_left.wait(lock, [&] { return job.helpers_inside == 0; });
}

void ThreadPool::worker_loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    Job* job = queue_.front();
    ++job->helpers_inside;
    if (--job->helpers_wanted == 0) queue_.pop_front();
    lock.unlock();
    take_tasks(job->task, job->user, job->count, job->next);
    lock.lock();
    // Notified under the mutex: the caller cannot return (and free the job) before it is released.
    if (--job->helpers_inside == 0) job->helpers_left.notify_all();
  }
}

}  // namespace pfx::host
