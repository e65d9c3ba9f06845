// Running pfx-view (and pfx-render) from the window tests: a finished run's exit code and output,
// or a viewer kept running to be signalled and watched, line by line, with time limits so a hung
// viewer fails the test instead of hanging it.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

#include "image.hpp"

namespace pfx::test {

struct RunResult {
  int exit_code = -1;  // 128 + signal when killed by one; -1 when it ran out of time
  std::string output;  // stdout and stderr together
};

// Runs argv[0] with the rest as arguments (no shell), at most timeout_seconds.
RunResult run_program(const std::vector<std::string>& argv, double timeout_seconds = 120);

class ViewerProcess {
 public:
  // Starts the program with stdout and stderr into one pipe.
  explicit ViewerProcess(const std::vector<std::string>& argv);
  ~ViewerProcess();  // kills the program if it still runs
  ViewerProcess(const ViewerProcess&) = delete;
  ViewerProcess& operator=(const ViewerProcess&) = delete;

  // Reads output until a line containing `text` arrives (after the lines already matched).
  // Returns that line, or "" when timeout_seconds pass or the program ends first.
  std::string wait_for_line(const std::string& text, double timeout_seconds);
  void send(int signal) const;
  // The exit code (128 + signal when killed by one), or -1 if it has not ended in time.
  int wait_exit(double timeout_seconds);
  // Everything the program printed so far, for failure messages.
  const std::string& output() const { return output_; }
  // The program's process id (to read its /proc entries while it runs).
  pid_t pid() const { return pid_; }

 private:
  bool read_more(std::chrono::steady_clock::time_point deadline);
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string output_;
  size_t consumed_ = 0;  // output_ before this has been matched already
  bool exited_ = false;
  int exit_code_ = -1;
};

// Largest and mean absolute difference of two 8-bit images of the same size (PNG files).
struct PngDifference {
  int width = 0, height = 0;
  int max = 0;
  double mean = 0;
};
PngDifference compare_png(const std::string& a, const std::string& b);

// Largest difference of two EXR images relative to max(1, |reference|), over RGB.
double exr_relative_difference(const std::string& a, const std::string& reference);

}  // namespace pfx::test
