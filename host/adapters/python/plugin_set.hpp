// The plugins a Python call works with: the files and folders it names (plugins=[...]), else the
// folder beside the module (build/plugins in a build tree, PREFIX/lib/pfx/plugins installed),
// then PFX_PLUGIN_PATH, as every pfx program looks for them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::python {

// A registry with those plugins loaded. A named file or folder that does not load raises
// pfx.Error; a plugin of the default folders that is refused is passed to `warn`.
std::unique_ptr<host::PluginRegistry> load_plugin_set(const std::optional<std::vector<std::string>>& plugins,
                                                      const std::function<void(const std::string&)>& warn);

}  // namespace pfx::python
