#include "inject_log.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace pfx::inject {

InjectLog::InjectLog(const std::string& path) {
  if (path.empty()) return;
  // O_CLOEXEC: the application's children do not inherit our file.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd >= 0) fd_ = fd;
  else line("cannot open the log file " + path + "; writing to stderr");
}

InjectLog::~InjectLog() {
  if (fd_ != 2) ::close(fd_);
}

void InjectLog::line(const std::string& message) {
  const std::string text = "pfx-inject: " + message + "\n";
  std::lock_guard<std::mutex> lock(mutex_);
  // One write per line, so lines of several threads or processes never interleave.
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n <= 0) break;
    written += static_cast<size_t>(n);
  }
}

bool InjectLog::once(const std::string& key, const std::string& message) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!said_.insert(key).second) return false;
  }
  line(message);
  return true;
}

}  // namespace pfx::inject
