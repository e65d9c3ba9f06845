#include "app_launch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <algorithm>
#include <filesystem>

#include "inject_options.hpp"
#include "vulkan_enable.hpp"
#include "plugin_directory.hpp"

#if defined(__SANITIZE_ADDRESS__)
#include <link.h>
#endif

extern char** environ;

namespace pfx::inject {
namespace {

#if defined(__SANITIZE_ADDRESS__)
// A sanitizer build (./run's second test pass) preloads an instrumented libpfxinject.so into an
// application that is not: AddressSanitizer's runtime must then be the first library of the
// process, so it goes in front, as this program has it loaded already.
std::string sanitizer_runtime() {
  std::string found;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "libasan.so")) {
          *static_cast<std::string*>(out) = info->dlpi_name;
          return 1;
        }
        return 0;
      },
      &found);
  return found;
}
#else
std::string sanitizer_runtime() { return ""; }
#endif

volatile pid_t forward_to = 0;

void forward_signal(int signal) {
  if (forward_to > 0) kill(forward_to, signal);
}

// While it lives, SIGINT, SIGTERM and SIGHUP sent to this program go to `child` instead.
class ForwardSignals {
 public:
  explicit ForwardSignals(pid_t child) {
    forward_to = child;
    struct sigaction action {};
    action.sa_handler = forward_signal;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &previous_[i]);
  }
  ~ForwardSignals() {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
    forward_to = 0;
  }

 private:
  static constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction previous_[3] {};
};

}  // namespace

std::string find_inject_library(std::string* error) {
  namespace fs = std::filesystem;
  const fs::path bin = app::executable_directory();
  // A build tree keeps libraries in build/lib; an install in its LIBDIR (lib/<triplet> on Debian).
  const fs::path build_tree = bin / ".." / "lib" / "libpfxinject.so";
  const fs::path installed = bin / PFX_INJECT_BIN_TO_LIB / "libpfxinject.so";
  std::error_code ec;
  for (const fs::path& path : {build_tree, installed})
    if (fs::is_regular_file(path, ec)) return fs::weakly_canonical(path, ec).string();
  *error = "libpfxinject.so not found at " + installed.string() + " (build it: cmake --build build --target pfxinject)";
  return "";
}

std::vector<std::string> plugin_folders(const InjectSettings& settings) {
  if (!settings.plugin_dirs.empty()) return settings.plugin_dirs;
  const std::string beside = app::default_plugin_directory();
  return beside.empty() ? std::vector<std::string>{} : std::vector<std::string>{beside};
}

std::vector<std::string> child_environment(const InjectSettings& settings, const std::string& library) {
  std::vector<std::string> environment;
  const std::string runtime = sanitizer_runtime();
  std::string preload = runtime.empty() ? library : runtime + ":" + library;
  for (char** entry = environ; *entry; ++entry) {
    const std::string variable = *entry;
    if (variable.rfind("PFX_INJECT_", 0) == 0) continue;
    if (!runtime.empty() && variable.rfind("ASAN_OPTIONS=", 0) == 0) {
      // The application's own allocations are not ours to judge, and --quit-after ends it
      // with its objects alive: leak checking stays with pfx's own processes.
      environment.push_back(variable + ":detect_leaks=0");
      continue;
    }
    if (variable.rfind("LD_PRELOAD=", 0) == 0) {
      const std::string others = variable.substr(std::strlen("LD_PRELOAD="));
      if (!others.empty()) preload += ":" + others;
      continue;
    }
    environment.push_back(variable);
  }
  environment.push_back("LD_PRELOAD=" + preload);
  std::vector<std::string> replaced;
  const std::vector<std::string> vulkan = vulkan_layer_environment(environment, &replaced);
  for (const auto& name : replaced)
    environment.erase(std::remove_if(environment.begin(), environment.end(),
                                     [&](const std::string& v) { return v.rfind(name + "=", 0) == 0; }),
                      environment.end());
  environment.insert(environment.end(), vulkan.begin(), vulkan.end());
  InjectSettings complete = settings;
  complete.plugin_dirs = plugin_folders(settings);
  for (const auto& variable : settings_to_environment(complete)) environment.push_back(variable);
  return environment;
}

int run_application(const std::vector<std::string>& command, const std::vector<std::string>& environment,
                    std::string* error) {
  std::vector<char*> argv, envp;
  for (const auto& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  for (const auto& variable : environment) envp.push_back(const_cast<char*>(variable.c_str()));
  envp.push_back(nullptr);
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) {
    *error = std::string("pipe: ") + std::strerror(errno);
    return exit_code::kInjectNotStarted;
  }
  const pid_t child = fork();
  if (child < 0) {
    *error = std::string("fork: ") + std::strerror(errno);
    return exit_code::kInjectNotStarted;
  }
  if (child == 0) {
    close(report[0]);
    execvpe(argv[0], argv.data(), envp.data());
    // Only reached when exec failed: tell the parent why through the pipe, which exec would close.
    const int failure = errno;
    (void)!write(report[1], &failure, sizeof failure);
    _exit(exit_code::kInjectNotStarted);
  }
  close(report[1]);
  // Ending pfx-inject (Ctrl+C, a script's kill) ends the application: the signal is passed on.
  ForwardSignals forward(child);
  int failure = 0;
  const bool exec_failed = read(report[0], &failure, sizeof failure) == sizeof failure;
  close(report[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (exec_failed) {
    *error = "cannot run " + command[0] + ": " + std::strerror(failure);
    return exit_code::kInjectNotStarted;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : exit_code::kSignalBase + WTERMSIG(status);
}

}  // namespace pfx::inject
