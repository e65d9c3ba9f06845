// The per-pass times of a chain injected into an application, as libpfxinject writes them for
// the live control panel (pfx-inject --panel): a small JSON file replaced a few times a second,
//   {"frame": 812, "timing": "finish+clock", "chain": "dof,bloom,glare", "total_ms": 3.2,
//    "passes": [{"effect": "bloom", "pass": "bright", "ms": 0.41}, ...]}
// read here whenever its modification time moves.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>

namespace pfx::app {

struct AppTimes {
  uint64_t frame = 0;  // the application's presented frame they were measured in; 0: none yet
  std::string timing, chain;
  pfx::host::FrameTimes times;
};

// Parses the file's text; false with *error when it is not that JSON.
bool parse_app_times(const std::string& json, AppTimes* out, std::string* error);

class AppTimingsReader {
 public:
  explicit AppTimingsReader(std::string path) : path_(std::move(path)) {}
  // Once a frame. Reads the file again when it changed, at most every quarter second or every 16th
  // call, whichever comes first (a clock stopped by libfaketime would otherwise keep it from ever
  // looking again); true when new times came.
  bool poll(double now_seconds);
  const AppTimes& latest() const { return latest_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  double last_look_ = -1;
  int polls_since_look_ = 0;
  long long stamp_ = -1;
  AppTimes latest_;
};

}  // namespace pfx::app
