// The injector's messages: one line each, "pfx-inject: ...", to stderr or to the --log file.
// Inside somebody else's application a problem is said once and then the frames pass through, so
// the log can also say a thing only the first time.
#pragma once

#include <mutex>
#include <set>
#include <string>

namespace pfx::inject {

class InjectLog {
 public:
  // An empty path, or one that cannot be opened for appending, writes to stderr.
  explicit InjectLog(const std::string& path);
  ~InjectLog();
  InjectLog(const InjectLog&) = delete;
  InjectLog& operator=(const InjectLog&) = delete;

  void line(const std::string& message);
  // Writes the message the first time `key` is seen; false when it was seen before.
  bool once(const std::string& key, const std::string& message);

 private:
  std::mutex mutex_;
  int fd_ = 2;
  std::set<std::string> said_;
};

}  // namespace pfx::inject
