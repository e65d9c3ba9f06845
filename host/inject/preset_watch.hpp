// Notices that the preset file changed, so an edit applies while the application runs. Looks at
// the file's modification time and size at most four times a second, from the present call.
#pragma once

#include <chrono>
#include <string>

namespace pfx::inject {

class PresetWatch {
 public:
  explicit PresetWatch(std::string path);
  // True once after each change (a new modification time or size, or the file appearing or
  // disappearing) seen since the last call that returned true.
  bool changed();

 private:
  std::string path_;
  std::chrono::steady_clock::time_point next_look_;
  long long stamp_ = -1, size_ = -1;
};

}  // namespace pfx::inject
