#include "pfx/host/plugin_watcher.hpp"

#include <sys/stat.h>

namespace pfx::host {

PluginWatcher::Signature PluginWatcher::signature_of(const std::string& path) {
  Signature signature;
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return signature;
  signature.exists = true;
  signature.size = static_cast<uint64_t>(info.st_size);
  signature.inode = static_cast<uint64_t>(info.st_ino);
  signature.mtime_ns = int64_t(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec;
  return signature;
}

void PluginWatcher::watch(const std::string& plugin_id, const std::string& path) {
  Watched watched;
  watched.path = path;
  watched.loaded = signature_of(path);
  watched_[plugin_id] = watched;
}

void PluginWatcher::forget(const std::string& plugin_id) { watched_.erase(plugin_id); }

std::vector<std::string> PluginWatcher::poll(double now_seconds) {
  std::vector<std::string> ready;
  for (auto& [id, watched] : watched_) {
    const Signature now = signature_of(watched.path);
    if (now == watched.loaded) {
      watched.changing = false;  // changed and changed back: nothing to do
      continue;
    }
    if (!watched.changing || now != watched.pending) {
      watched.changing = true;
      watched.pending = now;
      watched.pending_since = now_seconds;
      continue;
    }
    if (now.exists && now_seconds - watched.pending_since >= settle_seconds_) {
      ready.push_back(id);
      watched.loaded = now;
      watched.changing = false;
    }
  }
  return ready;
}

}  // namespace pfx::host
