#include "pfx/host/log.hpp"

#include <cstdio>
#include <mutex>

namespace pfx::host {

const char* log_level_name(pfx_log_level level) {
  switch (level) {
    case PFX_LOG_DEBUG: return "debug";
    case PFX_LOG_INFO: return "info";
    case PFX_LOG_WARNING: return "warning";
    case PFX_LOG_ERROR: return "error";
    default: return "log";
  }
}

LogSink stderr_log_sink(pfx_log_level min_level) {
  return [min_level](pfx_log_level level, const std::string& source, const std::string& message) {
    if (level < min_level) return;
    // Plugins may log from any thread (core.h promises it is thread-safe).
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    std::fprintf(stderr, "pfx: %s: [%s] %s\n", log_level_name(level), source.c_str(), message.c_str());
  };
}

}  // namespace pfx::host
