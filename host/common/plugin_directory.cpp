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

}  // namespace pfx::app
