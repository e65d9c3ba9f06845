// Where libpfxhost and the plugins it loads send their messages. The embedding program decides
// what to do with them; by default they go to stderr with a level prefix.
#pragma once

#include <functional>
#include <string>

#include <pfx/core.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

// source: "host" for the runtime itself, otherwise the plugin id.
using LogSink = std::function<void(pfx_log_level level, const std::string& source, const std::string& message)>;

PFX_HOST_API const char* log_level_name(pfx_log_level level);
// A sink writing "pfx: warning: [org.pfx.bloom] message" to stderr, dropping levels below min_level.
PFX_HOST_API LogSink stderr_log_sink(pfx_log_level min_level = PFX_LOG_INFO);

}  // namespace pfx::host
