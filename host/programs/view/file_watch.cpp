#include "file_watch.hpp"

#include <sys/stat.h>

namespace pfx::app {

bool FileWatch::changed(const std::vector<std::string>& files) {
  std::map<std::string, Stamp> now;
  bool any = false;
  for (const auto& file : files) {
    Stamp stamp;
    struct stat info {};
    if (::stat(file.c_str(), &info) == 0) {
      stamp.time = static_cast<long long>(info.st_mtim.tv_sec) * 1000000000LL + info.st_mtim.tv_nsec;
      stamp.size = static_cast<long long>(info.st_size);
      stamp.inode = static_cast<unsigned long long>(info.st_ino);
    }
    const auto before = seen_.find(file);
    any = any || (before != seen_.end() && before->second != stamp);
    now[file] = stamp;
  }
  seen_ = std::move(now);
  return any;
}

}  // namespace pfx::app
