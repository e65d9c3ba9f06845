// The process and thread state a plugin must leave as it found it (docs/sdk.md §1.6): taken before
// and after a plugin call on the calling thread, and compared. Each difference is one sentence
// naming what changed, from what to what.
#pragma once

#include <sched.h>
#include <signal.h>
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pfx::validate {

struct SignalDisposition {
  bool queried = false;       // false where sigaction refuses the signal (glibc's own ones)
  uintptr_t handler = 0;      // sa_handler or sa_sigaction, as a number
  int flags = 0;
  std::vector<int> mask;      // the signals blocked while the handler runs
};

struct ProcessState {
  // The calling thread.
  cpu_set_t affinity;
  int policy = 0, priority = 0, nice = 0;
  std::vector<int> blocked;   // the signal mask
  bool thread_locale_global = true;  // uselocale: the thread follows the global locale
  // The floating-point environment of the calling thread.
  int rounding = 0;
  int traps = 0;              // the exceptions that trap (fegetexcept)
  uint32_t mxcsr_control = 0; // x86: MXCSR without its sticky flags (FTZ, DAZ, masks, rounding)
  uint16_t x87_control = 0;   // x86: the x87 control word (masks, precision, rounding)
  // The process.
  std::vector<SignalDisposition> handlers;  // index: the signal number
  std::string c_locale;       // setlocale(LC_ALL, NULL)
  std::string cpp_locale;     // std::locale().name()
  std::string working_directory;
  std::vector<std::string> environment;  // sorted
  int umask = -1;             // /proc/self/status; -1 where the kernel does not give it
  int threads = 0;            // entries of /proc/self/task
};

ProcessState snapshot_process_state();
// What differs, e.g. "the C locale changed from 'C' to 'C.UTF-8'"; empty when nothing does.
std::vector<std::string> process_state_changes(const ProcessState& before, const ProcessState& after);

}  // namespace pfx::validate
