#include "obj_helper_thread.hpp"

#include <system_error>
#include <utility>
#include <vector>

namespace pfx_obj {

HelperThread::HelperThread(unsigned index, std::function<void()> body) : body_(std::move(body)) {
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  const int here = ::sched_getcpu();
  if (here >= 0 && ::sched_getaffinity(0, sizeof allowed_, &allowed_) == 0) {
    std::vector<int> cpus;
    size_t from = 0;
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
      if (CPU_ISSET(cpu, &allowed_)) {
        if (cpu == here) from = cpus.size();
        cpus.push_back(cpu);
      }
    if (cpus.size() > 1) {
      cpu_set_t first;
      CPU_ZERO(&first);
      CPU_SET(cpus[(from + index) % cpus.size()], &first);
      restore_ = pthread_attr_setaffinity_np(&attributes, sizeof first, &first) == 0;
    }
  }
  const int failed = pthread_create(&thread_, &attributes, &HelperThread::start, this);
  pthread_attr_destroy(&attributes);
  if (failed) throw std::system_error(failed, std::generic_category(), "cannot start a thread");
}

HelperThread::~HelperThread() { pthread_join(thread_, nullptr); }

void* HelperThread::start(void* self) {
  auto* helper = static_cast<HelperThread*>(self);
  if (helper->restore_) ::sched_setaffinity(0, sizeof helper->allowed_, &helper->allowed_);
  helper->body_();
  return nullptr;
}

}  // namespace pfx_obj
