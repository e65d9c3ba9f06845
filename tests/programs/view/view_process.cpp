#include "view_process.hpp"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "exr_io.hpp"
#include "png_io.hpp"

namespace pfx::test {
namespace {

using Clock = std::chrono::steady_clock;

pid_t spawn(const std::vector<std::string>& argv, int out_fd, int err_fd) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = fork();
  if (pid == 0) {
    dup2(out_fd, 1);
    dup2(err_fd, 2);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

int decode_status(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

Clock::time_point after(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace

RunResult run_program(const std::vector<std::string>& argv, double timeout_seconds) {
  ViewerProcess process(argv);
  RunResult result;
  result.exit_code = process.wait_exit(timeout_seconds);
  result.output = process.output();
  return result;
}

ViewerProcess::ViewerProcess(const std::vector<std::string>& argv) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  pid_ = spawn(argv, fds[1], fds[1]);
  close(fds[1]);
  fd_ = fds[0];
  REQUIRE(pid_ > 0);
}

ViewerProcess::~ViewerProcess() {
  if (!exited_ && pid_ > 0) {
    kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  if (fd_ >= 0) close(fd_);
}

bool ViewerProcess::read_more(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  if (left <= 0 || fd_ < 0) return false;
  pollfd p{fd_, POLLIN, 0};
  if (poll(&p, 1, int(std::min<long long>(left, 100))) <= 0) return true;  // nothing yet: try again
  char buffer[4096];
  ssize_t n = read(fd_, buffer, sizeof buffer);
  if (n <= 0) {
    close(fd_);
    fd_ = -1;
    return false;
  }
  output_.append(buffer, size_t(n));
  return true;
}

std::string ViewerProcess::wait_for_line(const std::string& text, double timeout_seconds) {
  const Clock::time_point deadline = after(timeout_seconds);
  for (;;) {
    size_t found = output_.find(text, consumed_);
    if (found != std::string::npos) {
      size_t end = output_.find('\n', found);
      if (end != std::string::npos) {
        size_t begin = output_.rfind('\n', found);
        begin = begin == std::string::npos ? 0 : begin + 1;
        consumed_ = end + 1;
        return output_.substr(begin, end - begin);
      }
    }
    if (!read_more(deadline)) return "";
  }
}

void ViewerProcess::send(int signal) const { kill(pid_, signal); }

int ViewerProcess::wait_exit(double timeout_seconds) {
  const Clock::time_point deadline = after(timeout_seconds);
  while (!exited_) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      exit_code_ = decode_status(status);
      break;
    }
    if (Clock::now() >= deadline) return -1;
    if (!read_more(deadline)) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  while (read_more(after(1.0)) && fd_ >= 0) {
  }
  return exit_code_;
}

PngDifference compare_png(const std::string& a, const std::string& b) {
  pfx::app::DisplayImage x, y;
  std::string error;
  INFO(error);
  REQUIRE(pfx::app::read_png(a, &x, &error));
  REQUIRE(pfx::app::read_png(b, &y, &error));
  REQUIRE(x.width == y.width);
  REQUIRE(x.height == y.height);
  REQUIRE(x.channels == y.channels);
  PngDifference d;
  d.width = x.width;
  d.height = x.height;
  double sum = 0;
  for (size_t i = 0; i < x.pixels.size(); ++i) {
    int diff = std::abs(int(x.pixels[i]) - int(y.pixels[i]));
    d.max = std::max(d.max, diff);
    sum += diff;
  }
  d.mean = x.pixels.empty() ? 0 : sum / double(x.pixels.size());
  return d;
}

double exr_relative_difference(const std::string& a, const std::string& reference) {
  pfx::app::Image x, y;
  std::string error;
  INFO(error);
  REQUIRE(pfx::app::read_exr(a, &x, &error));
  REQUIRE(pfx::app::read_exr(reference, &y, &error));
  REQUIRE(x.width == y.width);
  REQUIRE(x.height == y.height);
  double worst = 0;
  for (size_t i = 0; i < x.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    worst = std::max(worst, std::abs(double(x.rgba[i]) - y.rgba[i]) / std::max(1.0, std::abs(double(y.rgba[i]))));
  }
  return worst;
}

}  // namespace pfx::test
