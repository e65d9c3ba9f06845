// Notices rebuilt plugin files, for hot reload. It polls (one stat per file): that works on every
// file system, in containers and over network mounts, and costs microseconds per call.
//
// A linker writes a library in several steps, so a change is reported only once the file has
// stayed the same (size, modification time, inode) for `settle_seconds`; a file that is missing
// is waited for. Each change is reported once, whether or not the reload then succeeds: a failed
// build is retried when the file changes again.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "pfx/host/api.hpp"

namespace pfx::host {

class PFX_HOST_API PluginWatcher {
 public:
  explicit PluginWatcher(double settle_seconds = 0.2) : settle_seconds_(settle_seconds) {}

  // Starts (or restarts) watching `path` for plugin `plugin_id`, as the file is now.
  void watch(const std::string& plugin_id, const std::string& path);
  void forget(const std::string& plugin_id);

  // `now_seconds`: any steady clock. Returns the ids of the plugins whose file changed and then
  // stayed unchanged for settle_seconds.
  std::vector<std::string> poll(double now_seconds);

 private:
  struct Signature {
    bool exists = false;
    uint64_t size = 0, inode = 0;
    int64_t mtime_ns = 0;
    bool operator==(const Signature& o) const {
      return exists == o.exists && size == o.size && inode == o.inode && mtime_ns == o.mtime_ns;
    }
    bool operator!=(const Signature& o) const { return !(*this == o); }
  };
  struct Watched {
    std::string path;
    Signature loaded;   // the file the running version came from
    Signature pending;  // the latest different state seen
    bool changing = false;
    double pending_since = 0;
  };
  static Signature signature_of(const std::string& path);

  double settle_seconds_;
  std::map<std::string, Watched> watched_;
};

}  // namespace pfx::host
