#include "plugin_set.hpp"

#include <filesystem>

#include "adapter_plugins.hpp"
#include "headless_context.hpp"
#include "python_errors.hpp"

namespace pfx::python {
namespace {

// Any function of this library: dladdr finds the module's file from it.
void module_marker() {}

}  // namespace

std::unique_ptr<host::PluginRegistry> load_plugin_set(const std::optional<std::vector<std::string>>& plugins,
                                                      const std::function<void(const std::string&)>& warn) {
  auto registry = std::make_unique<host::PluginRegistry>(
      [](const char* name) { return app::HeadlessContext::get_proc_address(nullptr, name); },
      host::stderr_log_sink(PFX_LOG_WARNING), "pfx Python module " PFX_VERSION);
  if (!plugins) {
    const adapters::PluginFolderRule rule{adapters::library_path_of(reinterpret_cast<const void*>(&module_marker)),
                                          {"../plugins", PFX_PYTHON_TO_PLUGINS}};
    for (const auto& message : adapters::load_adapter_plugins(*registry, rule)) warn(message);
    return registry;
  }
  for (const auto& path : *plugins) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
      const auto refused = registry->load_directory(path);
      if (!refused.empty()) throw Error(refused.front());
    } else if (std::string error; !registry->load(path, &error)) {
      throw Error(error);
    }
  }
  // A source file a plugin could not use refuses no plugin: it gave no effect, and is said so.
  for (const auto& message : registry->source_errors()) warn("no effect from " + message);
  return registry;
}

}  // namespace pfx::python
