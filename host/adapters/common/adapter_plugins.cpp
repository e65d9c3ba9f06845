#include "adapter_plugins.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace pfx::adapters {

std::string library_path_of(const void* symbol) {
  Dl_info info{};
  if (!dladdr(symbol, &info) || !info.dli_fname) return "";
  return info.dli_fname;
}

std::vector<std::string> load_adapter_plugins(host::PluginRegistry& registry, const PluginFolderRule& rule) {
  std::vector<std::string> folders;
  std::error_code ec;
  const fs::path beside = fs::path(rule.library).parent_path();
  for (const auto& candidate : rule.candidates) {
    const fs::path folder = beside / candidate;
    if (!rule.library.empty() && fs::is_directory(folder, ec)) {
      folders.push_back(fs::weakly_canonical(folder, ec).string());
      break;
    }
  }
  std::vector<std::string> messages = registry.load_search_path(folders);
  for (const auto& message : registry.source_errors()) messages.push_back("no effect from " + message);
  const char* path = std::getenv("PFX_PLUGIN_PATH");
  if (folders.empty() && (!path || !*path)) {
    std::string tried;
    for (const auto& candidate : rule.candidates) tried += (tried.empty() ? "" : ", ") + (beside / candidate).string();
    messages.push_back("no pfx plugin folder beside " + rule.library + " (tried " + tried +
                       "): install the plugins there or name their folder in PFX_PLUGIN_PATH");
  }
  return messages;
}

}  // namespace pfx::adapters
