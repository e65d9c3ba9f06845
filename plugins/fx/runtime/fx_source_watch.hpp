#pragma once
// The files an FX effect was compiled from (the file and its includes), looked at for edits: a few
// stat calls every kIntervalMs, often enough that an edit shows within half a second (its compile
// included), rare enough to cost nothing next to a frame. Both runtimes' instances reload with it.
#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "effect_compiler.hpp"

namespace pfx_fx {

class SourceWatch {
 public:
  // Watches the files `compiled` read, as they are now (`file` alone when it read none: the file
  // could not be opened, so any file that appears there counts as an edit).
  void watch(const pfx::fx::CompiledEffect& compiled, const std::string& file);
  // Whether a watched file changed since watch(). Looks only when kIntervalMs have passed since
  // the last look (false in between), or at once after look_next_time().
  bool edited();
  void look_next_time() { last_look_ = {}; }

 private:
  static constexpr int kIntervalMs = 100;
  std::vector<std::pair<std::string, std::filesystem::file_time_type>> files_;
  std::chrono::steady_clock::time_point last_look_{};
};

}  // namespace pfx_fx
