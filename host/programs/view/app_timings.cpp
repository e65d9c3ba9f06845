#include "app_timings.hpp"

#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace pfx::app {

bool parse_app_times(const std::string& json, AppTimes* out, std::string* error) {
  const auto root = nlohmann::json::parse(json, nullptr, false);
  if (root.is_discarded() || !root.is_object() || !root.contains("frame") || !root.contains("passes") ||
      !root["passes"].is_array()) {
    *error = "not the injector's timings";
    return false;
  }
  AppTimes times;
  times.frame = root.value("frame", uint64_t(0));
  times.timing = root.value("timing", std::string());
  times.chain = root.value("chain", std::string());
  times.times.frame = times.frame;
  times.times.total_ms = root.value("total_ms", 0.0);
  for (const auto& pass : root["passes"]) {
    if (!pass.is_object()) continue;
    times.times.passes.push_back(
        {pass.value("effect", std::string()), pass.value("pass", std::string()), pass.value("ms", 0.0)});
  }
  *out = std::move(times);
  return true;
}

bool AppTimingsReader::poll(double now_seconds) {
  if (path_.empty() || (last_look_ >= 0 && now_seconds - last_look_ < 0.25 && ++polls_since_look_ < 16)) return false;
  last_look_ = now_seconds;
  polls_since_look_ = 0;
  struct stat info {};
  if (::stat(path_.c_str(), &info) != 0) return false;
  const long long stamp = static_cast<long long>(info.st_mtim.tv_sec) * 1000000000LL + info.st_mtim.tv_nsec;
  if (stamp == stamp_) return false;
  std::ifstream file(path_);
  std::stringstream text;
  text << file.rdbuf();
  AppTimes times;
  std::string error;
  // The writer replaces the file whole (rename), so a read sees one version or the other.
  if (!parse_app_times(text.str(), &times, &error)) return false;
  stamp_ = stamp;
  latest_ = std::move(times);
  return true;
}

}  // namespace pfx::app
