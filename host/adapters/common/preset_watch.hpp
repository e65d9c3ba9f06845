// Notices that the preset file changed, so an edit applies while the application runs. Looks at
// the file's modification time and size from the present call, ten times a second or every
// 16th present, whichever comes first: a clock stopped by libfaketime (the tests run
// applications so) must not stop the watch.
#pragma once

#include <chrono>
#include <string>

namespace pfx::inject {

class PresetWatch {
 public:
  explicit PresetWatch(std::string path);
  // True once after each change (a new modification time, size or inode, or the file appearing
  // or disappearing) seen since the last call that returned true.
  bool changed();

 private:
  std::string path_;
  std::chrono::steady_clock::time_point next_look_;
  int presents_since_look_ = 0;
  long long stamp_ = -1, size_ = -1;
  unsigned long long inode_ = 0;
};

}  // namespace pfx::inject
