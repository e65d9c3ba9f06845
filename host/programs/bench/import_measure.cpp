#include "import_measure.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "exit_codes.hpp"
#include "plugin_directory.hpp"

namespace pfx::bench {

namespace {

double cpu_seconds_so_far() {
  struct rusage usage {};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

uint64_t status_kib(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const size_t length = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, length, field) == 0) return std::stoull(line.substr(length + 1));
  return 0;
}

void write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

}  // namespace

bool run_self(const std::vector<std::string>& args, std::string* output, int* status) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& arg : copy) argv.push_back(arg.data());
  argv.push_back(nullptr);
  int fds[2];
  if (::pipe(fds) != 0) return false;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if (child == 0) {
    ::close(fds[0]);
    if (::dup2(fds[1], STDOUT_FILENO) < 0) ::_exit(127);
    ::close(fds[1]);
    ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  output->clear();
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0) output->append(buffer, static_cast<size_t>(n));
  ::close(fds[0]);
  ::waitpid(child, status, 0);
  return true;
}

LoadMeasure measure_in_new_process(const std::string& loader, const std::string& path, unsigned threads,
                                   const std::vector<std::string>& plugin_dirs) {
  LoadMeasure measure;
  std::vector<std::string> args = {"pfx-bench", "--import-load", loader, path, std::to_string(threads)};
  for (const auto& dir : plugin_dirs) {
    args.push_back("--plugins");
    args.push_back(dir);
  }
  std::string text;
  int status = 0;
  if (!run_self(args, &text, &status)) {
    measure.counts.error = std::string("cannot start a process: ") + std::strerror(errno);
    return measure;
  }
  std::istringstream in(text);
  int ok = 0;
  if (!(in >> ok >> measure.seconds >> measure.cpu_seconds >> measure.peak_bytes >> measure.counts.vertices >> measure.counts.triangles)) {
    measure.counts.error = WIFSIGNALED(status) ? "the loader died (signal " + std::to_string(WTERMSIG(status)) + ")"
                           : WIFEXITED(status) && WEXITSTATUS(status) == 127 ? "could not run pfx-bench --import-load"
                                                                             : "the loader's process reported nothing";
    return measure;
  }
  measure.counts.ok = ok == 1;
  in.get();
  std::getline(in, measure.counts.error, '\0');
  return measure;
}

int import_load_main(const std::vector<std::string>& args) {
  // LOADER FILE THREADS [--plugins DIR]...
  unsigned threads = 0;
  std::vector<std::string> plugin_dirs;
  bool ok = args.size() >= 3 && (args.size() - 3) % 2 == 0;
  if (ok) {
    char* end = nullptr;
    const long n = std::strtol(args[2].c_str(), &end, 10);
    ok = *end == 0 && n >= 1 && n <= 1024;
    threads = static_cast<unsigned>(n);
  }
  for (size_t i = 3; ok && i + 1 < args.size(); i += 2) {
    ok = args[i] == "--plugins";
    plugin_dirs.push_back(args[i + 1]);
  }
  if (!ok) {
    std::fprintf(stderr, "pfx-bench: --import-load LOADER FILE THREADS [--plugins DIR]...: an internal mode of "
                         "pfx-bench --import, which runs it once per load\n");
    return exit_code::kUsage;
  }
  pfx::host::PluginRegistry registry([](const char*) { return pfx_gl_proc{nullptr}; },
                                     pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-bench");
  if (args[0] == "pfx") pfx::app::load_plugins(registry, plugin_dirs);  // failures show as a failed load

  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";  // resets VmHWM to the current resident size
  }
  const uint64_t before = status_kib("VmRSS:");
  const double cpu_start = cpu_seconds_so_far();
  const auto start = std::chrono::steady_clock::now();
  const LoadCounts counts = load_with(args[0], args[1], threads, registry);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds_so_far() - cpu_start;
  const uint64_t peak = status_kib("VmHWM:");
  std::ostringstream out;
  out << (counts.ok ? 1 : 0) << ' ' << seconds << ' ' << cpu << ' ' << (peak > before ? (peak - before) * 1024 : 0) << ' '
      << counts.vertices << ' ' << counts.triangles << '\n'
      << counts.error;
  write_all(STDOUT_FILENO, out.str());
  return exit_code::kOk;
}

bool warm_file(const std::string& path, std::string* error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    *error = path + ": " + std::strerror(errno);
    return false;
  }
  static char buffer[1 << 20];
  while (::read(fd, buffer, sizeof buffer) > 0) {
  }
  // A file just generated is still being written back to disk: finish that now, so it does not
  // run during (and slow) the first loads.
  ::fdatasync(fd);
  ::close(fd);
  return true;
}

}  // namespace pfx::bench
