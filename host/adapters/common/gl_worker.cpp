#include "gl_worker.hpp"

#include "headless_context.hpp"

namespace pfx::adapters {
namespace {

std::mutex worker_mutex;
std::weak_ptr<GlWorker> current_worker;

}  // namespace

std::shared_ptr<GlWorker> GlWorker::acquire() {
  std::lock_guard<std::mutex> lock(worker_mutex);
  std::shared_ptr<GlWorker> worker = current_worker.lock();
  if (!worker) {
    worker.reset(new GlWorker);
    current_worker = worker;
  }
  return worker;
}

std::shared_ptr<GlWorker> GlWorker::start() { return std::shared_ptr<GlWorker>(new GlWorker); }

GlWorker::GlWorker() { thread_ = std::thread([this] { loop(); }); }

GlWorker::~GlWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void GlWorker::loop() {
  std::string error;
  // A guest's context: the display may be the host program's too, so it is never terminated.
  std::unique_ptr<app::HeadlessContext> context =
      app::HeadlessContext::create(&error, app::HeadlessContext::Display::SHARED);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    started_ = true;
    if (context) renderer_ = context->renderer();
    else context_error_ = error.empty() ? "no OpenGL 4.5 context" : error;
  }
  wake_.notify_all();
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stopping_ || (job_ && !job_done_); });
    if (job_ && !job_done_) {
      const std::function<void()>* job = job_;
      lock.unlock();
      if (context) (*job)();
      lock.lock();
      job_done_ = true;
      wake_.notify_all();
      continue;
    }
    if (stopping_) break;
  }
  lock.unlock();
  context.reset();
}

bool GlWorker::run(const std::function<void()>& job, std::string* error) {
  std::lock_guard<std::mutex> one_caller(callers_);
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [this] { return started_; });
  if (!context_error_.empty()) {
    *error = context_error_;
    return false;
  }
  job_ = &job;
  job_done_ = false;
  wake_.notify_all();
  wake_.wait(lock, [this] { return job_done_; });
  job_ = nullptr;
  return true;
}

}  // namespace pfx::adapters
