#include "plugin_directory.hpp"

#include <filesystem>

namespace fs = std::filesystem;

namespace pfx::app {

std::string executable_directory() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : exe.parent_path().string();
}

std::string default_plugin_directory() {
  const fs::path bin = executable_directory();
  std::error_code ec;
  for (const fs::path& candidate : {bin / ".." / "plugins", bin / ".." / "lib" / "pfx" / "plugins"})
    if (fs::is_directory(candidate, ec)) return fs::weakly_canonical(candidate, ec).string();
  return "";
}

std::vector<std::string> load_plugins(pfx::host::PluginRegistry& registry, const std::vector<std::string>& folders) {
  std::vector<std::string> search = folders;
  if (search.empty()) {
    std::string fallback = default_plugin_directory();
    if (!fallback.empty()) search.push_back(fallback);
  }
  return load_messages(registry, registry.load_search_path(search));
}

std::vector<std::string> load_messages(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& refused) {
  std::vector<std::string> messages;
  for (const auto& message : refused) messages.push_back("plugin not loaded: " + message);
  for (const auto& message : registry.source_errors()) messages.push_back("no effect from " + message);
  return messages;
}

}  // namespace pfx::app
