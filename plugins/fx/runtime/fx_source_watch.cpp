#include "fx_source_watch.hpp"

namespace pfx_fx {

void SourceWatch::watch(const pfx::fx::CompiledEffect& compiled, const std::string& file) {
  files_.clear();
  for (const std::string& path : compiled.front->preprocessed.included_files) {
    std::error_code ec;
    files_.emplace_back(path, std::filesystem::last_write_time(path, ec));
  }
  if (files_.empty()) files_.emplace_back(file, std::filesystem::file_time_type{});
}

bool SourceWatch::edited() {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_look_ < std::chrono::milliseconds(kIntervalMs)) return false;
  last_look_ = now;
  for (const auto& [path, time] : files_) {
    std::error_code ec;
    if (std::filesystem::last_write_time(path, ec) != time) return true;
  }
  return false;
}

}  // namespace pfx_fx
