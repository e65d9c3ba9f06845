// Where our programs look for plugins when --plugins is not given: build/plugins next to
// build/bin in a build tree, PREFIX/lib/pfx/plugins next to PREFIX/bin when installed.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::app {

// The folder of the running executable (from /proc/self/exe).
std::string executable_directory();
// The default plugin folder; empty when neither layout exists.
std::string default_plugin_directory();
// Loads the plugins of the given folders (the default folder when none is given) and of
// PFX_PLUGIN_PATH; returns a warning for every plugin or folder refused ("plugin not loaded:
// PATH: reason") and every source file that gave no effect ("no effect from FILE:LINE:COLUMN:
// error: ...", load_messages).
std::vector<std::string> load_plugins(pfx::host::PluginRegistry& registry, const std::vector<std::string>& folders);
// Those warnings for messages load_search_path returned, and the registry's source errors.
std::vector<std::string> load_messages(const pfx::host::PluginRegistry& registry, const std::vector<std::string>& refused);

}  // namespace pfx::app
