#include "vulkan_enable.hpp"

#include <filesystem>

#include "plugin_directory.hpp"

namespace pfx::inject {

std::vector<std::string> vulkan_layer_environment(const std::vector<std::string>& environment,
                                                  std::vector<std::string>* replaced) {
  namespace fs = std::filesystem;
  std::vector<std::string> variables = {"ENABLE_PFX_VULKAN=1"};
  std::error_code ec;
  const fs::path share = fs::path(app::executable_directory()) / ".." / "share";
  if (!fs::is_regular_file(share / "vulkan" / "implicit_layer.d" / "pfx_layer.json", ec)) return variables;
  // The loader's default when XDG_DATA_DIRS is unset (the XDG base directory specification's).
  std::string data_dirs = "/usr/local/share:/usr/share";
  for (const auto& variable : environment)
    if (variable.rfind("XDG_DATA_DIRS=", 0) == 0 && variable.size() > 14) data_dirs = variable.substr(14);
  variables.push_back("XDG_DATA_DIRS=" + fs::weakly_canonical(share, ec).string() + ":" + data_dirs);
  replaced->push_back("XDG_DATA_DIRS");
  return variables;
}

}  // namespace pfx::inject
