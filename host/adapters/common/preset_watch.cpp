#include "preset_watch.hpp"

#include <sys/stat.h>

namespace pfx::inject {
namespace {

constexpr std::chrono::milliseconds kLookInterval{100};
constexpr int kPresentsBetweenLooks = 16;

// The modification time, the size and the inode: a preset replaced the way editors and the panel
// write files (a new file renamed over the old) is a new inode even when its size is the same and
// the clock stands still (libfaketime fakes the times stat reports).
void look(const std::string& path, long long* stamp, long long* size, unsigned long long* inode) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    *stamp = *size = -1;
    *inode = 0;
    return;
  }
  *stamp = static_cast<long long>(info.st_mtim.tv_sec) * 1000000000LL + info.st_mtim.tv_nsec;
  *size = static_cast<long long>(info.st_size);
  *inode = static_cast<unsigned long long>(info.st_ino);
}

}  // namespace

PresetWatch::PresetWatch(std::string path) : path_(std::move(path)) {
  if (!path_.empty()) look(path_, &stamp_, &size_, &inode_);
  next_look_ = std::chrono::steady_clock::now() + kLookInterval;
}

bool PresetWatch::changed() {
  if (path_.empty()) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_look_ && ++presents_since_look_ < kPresentsBetweenLooks) return false;
  next_look_ = now + kLookInterval;
  presents_since_look_ = 0;
  long long stamp = 0, size = 0;
  unsigned long long inode = 0;
  look(path_, &stamp, &size, &inode);
  if (stamp == stamp_ && size == size_ && inode == inode_) return false;
  stamp_ = stamp;
  size_ = size;
  inode_ = inode;
  return true;
}

}  // namespace pfx::inject
