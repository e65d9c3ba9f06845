#include "obj_helper_thread.hpp"

#include <system_error>
#include <utility>

namespace pfx_obj {

WorkerPlacement::WorkerPlacement(unsigned workers) {
  CPU_ZERO(&allowed_);
  if (workers < 2) return;
  const int here = ::sched_getcpu();
  if (here < 0 || ::sched_getaffinity(0, sizeof allowed_, &allowed_) != 0) return;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &allowed_)) {
      if (cpu == here) here_ = cpus_.size();
      cpus_.push_back(cpu);
    }
  if (cpus_.size() < 2 || cpus_[here_] != here) {  // nothing to place, or here is outside the set
    cpus_.clear();
    return;
  }
  if (workers <= cpus_.size()) {
    cpu_set_t only;
    CPU_ZERO(&only);
    CPU_SET(here, &only);
    pinned_ = ::sched_setaffinity(0, sizeof only, &only) == 0;
  }
}

WorkerPlacement::~WorkerPlacement() {
  if (pinned_) ::sched_setaffinity(0, sizeof allowed_, &allowed_);
}

HelperThread::HelperThread(const WorkerPlacement& placement, unsigned index, std::function<void()> body)
    : body_(std::move(body)) {
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  const int cpu = placement.cpu_of(index);
  if (cpu >= 0) {
    cpu_set_t first;
    CPU_ZERO(&first);
    CPU_SET(cpu, &first);
    if (pthread_attr_setaffinity_np(&attributes, sizeof first, &first) == 0 && !placement.pinned())
      allow_after_start_ = &placement.allowed();
  }
  const int failed = pthread_create(&thread_, &attributes, &HelperThread::start, this);
  pthread_attr_destroy(&attributes);
  if (failed) throw std::system_error(failed, std::generic_category(), "cannot start a thread");
}

HelperThread::~HelperThread() { pthread_join(thread_, nullptr); }

void* HelperThread::start(void* self) {
  auto* helper = static_cast<HelperThread*>(self);
  if (helper->allow_after_start_) ::sched_setaffinity(0, sizeof *helper->allow_after_start_, helper->allow_after_start_);
  helper->body_();
  return nullptr;
}

}  // namespace pfx_obj
