#include "child_process.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace pfx::validate {
namespace {

constexpr size_t kStderrTail = 2000;

std::string read_all(std::FILE* file) {
  std::string text;
  std::rewind(file);
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
  return text;
}

void parse_line(const std::string& line, ChildReport* report) {
  const size_t tab = line.find('\t');
  const std::string kind = line.substr(0, tab);
  const std::string text = tab == std::string::npos ? "" : line.substr(tab + 1);
  if (kind == "step") report->steps.push_back(text);
  else if (kind == "problem") report->problems.push_back(text);
  else if (kind == "done") report->end = ChildReport::End::Finished;
  else if (kind == "fact") {
    const size_t eq = text.find('=');
    report->facts.emplace_back(text.substr(0, eq), eq == std::string::npos ? "" : text.substr(eq + 1));
  }
}

}  // namespace

void CheckReporter::send(const char* kind, const std::string& text) {
  std::string line = std::string(kind) + "\t" + text;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  line += '\n';
  // One write: a pipe write of up to PIPE_BUF bytes is atomic, longer ones are still written whole
  // unless the child dies in between, which only loses the line being written.
  size_t written = 0;
  while (written < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + written, line.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<size_t>(n);
  }
}

std::string ChildReport::abnormal_end() const {
  const std::string where = steps.empty() ? "" : " during: " + steps.back();
  switch (end) {
    case End::Finished: return "";
    case End::Exited:
      return "the check process exited with code " + std::to_string(exit_code) + " before finishing" + where;
    case End::Signalled:
      return "crashed with signal " + std::to_string(signal) + " (" + strsignal(signal) + ")" + where;
    case End::TimedOut: return "did not finish in time and was killed" + where;
    case End::ForkFailed: return std::string("could not start a child process: ") + std::strerror(exit_code);
  }
  return "";
}

std::string ChildReport::fact(const std::string& key) const {
  for (const auto& [k, v] : facts)
    if (k == key) return v;
  return "";
}

ChildReport run_in_child(const std::function<void(CheckReporter&)>& body, double timeout_s) {
  ChildReport report;
  std::FILE* out = std::tmpfile();
  std::FILE* err = std::tmpfile();
  int fds[2] = {-1, -1};
  if (!out || !err || ::pipe(fds) != 0) {
    report.end = ChildReport::End::ForkFailed;
    report.exit_code = errno;
    if (out) std::fclose(out);
    if (err) std::fclose(err);
    return report;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    ::dup2(::fileno(out), STDOUT_FILENO);
    ::dup2(::fileno(err), STDERR_FILENO);
    CheckReporter reporter(fds[1]);
    try {
      body(reporter);
    } catch (const std::exception& e) {
      reporter.problem(std::string("pfx-validate internal error: ") + e.what());
    }
    std::fflush(stdout);
    reporter.done();
    // _exit: the parent's atexit handlers and buffered streams are not the child's to run.
    ::_exit(0);
  }
  ::close(fds[1]);
  if (pid < 0) {
    report.end = ChildReport::End::ForkFailed;
    report.exit_code = errno;
    ::close(fds[0]);
    std::fclose(out);
    std::fclose(err);
    return report;
  }

  // Read lines until the child closes the pipe (it exited) or the time is up.
  report.end = ChildReport::End::Exited;  // until "done" arrives
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::string pending;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, static_cast<size_t>(n));
    size_t newline;
    while ((newline = pending.find('\n')) != std::string::npos) {
      parse_line(pending.substr(0, newline), &report);
      pending.erase(0, newline + 1);
    }
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    report.end = ChildReport::End::TimedOut;
  } else if (WIFSIGNALED(status)) {
    report.end = ChildReport::End::Signalled;
    report.signal = WTERMSIG(status);
  } else if (report.end != ChildReport::End::Finished || WEXITSTATUS(status) != 0) {
    report.end = ChildReport::End::Exited;
    report.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  report.stdout_text = read_all(out);
  report.stderr_text = read_all(err);
  if (report.stderr_text.size() > kStderrTail)
    report.stderr_text = "..." + report.stderr_text.substr(report.stderr_text.size() - kStderrTail);
  std::fclose(out);
  std::fclose(err);
  return report;
}

}  // namespace pfx::validate
