#include "process_state.hpp"

#include <dirent.h>
#include <locale.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cfenv>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <locale>

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#define PFX_VALIDATE_X86 1
#endif

extern char** environ;

namespace pfx::validate {
namespace {

std::vector<int> members(const sigset_t& set) {
  std::vector<int> out;
  for (int sig = 1; sig < NSIG; ++sig)
    if (sigismember(&set, sig) == 1) out.push_back(sig);
  return out;
}

int count_threads() {
  int n = 0;
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (dirent* entry = readdir(tasks))
      if (entry->d_name[0] != '.') ++n;
    closedir(tasks);
  }
  return n;
}

std::string signal_name(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  if (abbrev) return "SIG" + std::string(abbrev) + " (" + std::to_string(sig) + ")";
  if (sig >= SIGRTMIN && sig <= SIGRTMAX) return "SIGRTMIN+" + std::to_string(sig - SIGRTMIN) + " (" + std::to_string(sig) + ")";
  return "signal " + std::to_string(sig);
}

std::string signal_list(const std::vector<int>& signals) {
  if (signals.empty()) return "none";
  std::string text;
  for (int sig : signals) text += (text.empty() ? "" : ", ") + signal_name(sig);
  return text;
}

std::string cpu_list(const cpu_set_t& set) {
  std::string text;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &set)) text += (text.empty() ? "" : ",") + std::to_string(cpu);
  return "{" + text + "}";
}

std::string handler_text(const SignalDisposition& d) {
  if (!d.queried) return "(not queryable)";
  if (d.handler == reinterpret_cast<uintptr_t>(SIG_DFL)) return "SIG_DFL";
  if (d.handler == reinterpret_cast<uintptr_t>(SIG_IGN)) return "SIG_IGN";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "a handler at %#zx", static_cast<size_t>(d.handler));
  return buffer;
}

std::string rounding_text(int mode) {
  switch (mode) {
    case FE_TONEAREST: return "to nearest";
    case FE_TOWARDZERO: return "toward zero";
    case FE_UPWARD: return "upward";
    case FE_DOWNWARD: return "downward";
  }
  return std::to_string(mode);
}

std::string exceptions_text(int set) {
  std::string text;
  const std::pair<int, const char*> names[] = {{FE_INVALID, "invalid"}, {FE_DIVBYZERO, "divide-by-zero"},
                                               {FE_OVERFLOW, "overflow"}, {FE_UNDERFLOW, "underflow"},
                                               {FE_INEXACT, "inexact"}};
  for (const auto& [bit, name] : names)
    if (set & bit) text += (text.empty() ? "" : ", ") + std::string(name);
  return text.empty() ? "none" : text;
}

std::string hex(uint32_t value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "%#06x", value);
  return buffer;
}

std::string octal(mode_t value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "%04o", static_cast<unsigned>(value));
  return buffer;
}

// "FOO=1 added", "BAR=2 removed" for the entries in only one of the two sorted lists.
std::vector<std::string> environment_changes(const std::vector<std::string>& before, const std::vector<std::string>& after) {
  std::vector<std::string> gone, added, out;
  std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(gone));
  std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(added));
  for (const std::string& entry : added) out.push_back("the environment gained '" + entry + "'");
  for (const std::string& entry : gone) out.push_back("the environment lost '" + entry + "'");
  return out;
}

// The umask as the kernel reports it (Linux 4.7 and later), never by umask(2): that call reads it
// only by setting it, and two snapshots taken at once on different threads would each read the
// other's temporary value and restore it, leaving the process with a umask of 0. -1 when the
// kernel does not say.
int read_umask() {
  std::FILE* status = std::fopen("/proc/self/status", "re");
  if (!status) return -1;
  int value = -1;
  char line[256];
  while (std::fgets(line, sizeof line, status)) {
    unsigned mask = 0;
    if (std::sscanf(line, "Umask: %o", &mask) == 1) {
      value = static_cast<int>(mask);
      break;
    }
  }
  std::fclose(status);
  return value;
}

}  // namespace

ProcessState snapshot_process_state() {
  ProcessState s;
  CPU_ZERO(&s.affinity);
  sched_getaffinity(0, sizeof s.affinity, &s.affinity);
  sched_param param{};
  pthread_getschedparam(pthread_self(), &s.policy, &param);
  s.priority = param.sched_priority;
  errno = 0;
  s.nice = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  sigset_t blocked;
  sigemptyset(&blocked);
  pthread_sigmask(SIG_BLOCK, nullptr, &blocked);
  s.blocked = members(blocked);
  s.thread_locale_global = uselocale(static_cast<locale_t>(0)) == LC_GLOBAL_LOCALE;

  s.rounding = fegetround();
  s.traps = fegetexcept();
#if defined(PFX_VALIDATE_X86)
  s.mxcsr_control = _mm_getcsr() & ~0x3Fu;  // bits 0-5 are the sticky exception flags
  uint16_t control = 0;
  __asm__ volatile("fnstcw %0" : "=m"(control));
  s.x87_control = control;
#endif

  s.handlers.resize(NSIG);
  for (int sig = 1; sig < NSIG; ++sig) {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    SignalDisposition& d = s.handlers[sig];
    if (sigaction(sig, nullptr, &action) != 0) continue;
    d.queried = true;
    d.flags = action.sa_flags;
    d.handler = (action.sa_flags & SA_SIGINFO) ? reinterpret_cast<uintptr_t>(action.sa_sigaction)
                                               : reinterpret_cast<uintptr_t>(action.sa_handler);
    d.mask = members(action.sa_mask);
  }
  const char* c_locale = setlocale(LC_ALL, nullptr);
  s.c_locale = c_locale ? c_locale : "(null)";
  s.cpp_locale = std::locale().name();
  char cwd[PATH_MAX];
  s.working_directory = getcwd(cwd, sizeof cwd) ? cwd : "(unreadable: " + std::string(std::strerror(errno)) + ")";
  for (char** entry = environ; entry && *entry; ++entry) s.environment.emplace_back(*entry);
  std::sort(s.environment.begin(), s.environment.end());
  s.umask = read_umask();
  s.threads = count_threads();
  return s;
}

std::vector<std::string> process_state_changes(const ProcessState& before, const ProcessState& after) {
  std::vector<std::string> out;
  if (!CPU_EQUAL(&before.affinity, &after.affinity))
    out.push_back("the calling thread's CPU affinity changed from " + cpu_list(before.affinity) + " to " +
                  cpu_list(after.affinity));
  if (before.policy != after.policy || before.priority != after.priority)
    out.push_back("the calling thread's scheduling changed from policy " + std::to_string(before.policy) + " priority " +
                  std::to_string(before.priority) + " to policy " + std::to_string(after.policy) + " priority " +
                  std::to_string(after.priority));
  if (before.nice != after.nice)
    out.push_back("the calling thread's nice value changed from " + std::to_string(before.nice) + " to " +
                  std::to_string(after.nice));
  if (before.blocked != after.blocked)
    out.push_back("the calling thread's signal mask changed from [" + signal_list(before.blocked) + "] to [" +
                  signal_list(after.blocked) + "]");
  if (before.thread_locale_global != after.thread_locale_global)
    out.push_back(std::string("the calling thread's locale (uselocale) ") +
                  (after.thread_locale_global ? "was set back to the global locale" : "was set to a locale of its own"));
  if (before.rounding != after.rounding)
    out.push_back("the floating-point rounding mode changed from " + rounding_text(before.rounding) + " to " +
                  rounding_text(after.rounding));
  if (before.traps != after.traps)
    out.push_back("the floating-point exceptions that trap changed from [" + exceptions_text(before.traps) + "] to [" +
                  exceptions_text(after.traps) + "]");
  if (before.mxcsr_control != after.mxcsr_control) {
    std::string what;
    const uint32_t changed = before.mxcsr_control ^ after.mxcsr_control;
    if (changed & 0x8000u) what += (after.mxcsr_control & 0x8000u) ? ", flush-to-zero turned on" : ", flush-to-zero turned off";
    if (changed & 0x0040u)
      what += (after.mxcsr_control & 0x0040u) ? ", denormals-are-zero turned on" : ", denormals-are-zero turned off";
    out.push_back("MXCSR changed from " + hex(before.mxcsr_control) + " to " + hex(after.mxcsr_control) + what);
  }
  if (before.x87_control != after.x87_control)
    out.push_back("the x87 control word changed from " + hex(before.x87_control) + " to " + hex(after.x87_control));
  for (size_t sig = 1; sig < before.handlers.size() && sig < after.handlers.size(); ++sig) {
    const SignalDisposition &a = before.handlers[sig], &b = after.handlers[sig];
    if (a.queried != b.queried || a.handler != b.handler)
      out.push_back("the handler of " + signal_name(static_cast<int>(sig)) + " changed from " + handler_text(a) + " to " +
                    handler_text(b));
    else if (a.flags != b.flags || a.mask != b.mask)
      out.push_back("the sigaction flags or mask of " + signal_name(static_cast<int>(sig)) + " changed");
  }
  if (before.c_locale != after.c_locale)
    out.push_back("the C locale changed from '" + before.c_locale + "' to '" + after.c_locale + "'");
  if (before.cpp_locale != after.cpp_locale)
    out.push_back("the C++ global locale changed from '" + before.cpp_locale + "' to '" + after.cpp_locale + "'");
  if (before.working_directory != after.working_directory)
    out.push_back("the working directory changed from " + before.working_directory + " to " + after.working_directory);
  for (std::string& change : environment_changes(before.environment, after.environment)) out.push_back(std::move(change));
  if (before.umask != after.umask && before.umask >= 0 && after.umask >= 0)
    out.push_back("the umask changed from " + octal(static_cast<mode_t>(before.umask)) + " to " +
                  octal(static_cast<mode_t>(after.umask)));
  if (after.threads > before.threads)
    out.push_back(std::to_string(after.threads - before.threads) + " thread(s) left running (" +
                  std::to_string(before.threads) + " before the call, " + std::to_string(after.threads) + " after)");
  return out;
}

}  // namespace pfx::validate
