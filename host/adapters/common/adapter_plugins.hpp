// The pfx plugins an adapter library loads: those in the folder that the build tree or an install
// puts beside the library, then those of PFX_PLUGIN_PATH, as our programs do.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::adapters {

// The file of the shared library holding `symbol` (dladdr), or "" when it cannot be told.
std::string library_path_of(const void* symbol);

// Folders tried, each relative to the library's folder, in order: the first that exists is the
// plugin folder.
struct PluginFolderRule {
  std::string library;                  // the adapter library's file
  std::vector<std::string> candidates;  // e.g. "../pfx/plugins" (installed), "../../plugins" (build tree)
};

// Loads the plugins of the folder beside the library and of PFX_PLUGIN_PATH into `registry`;
// returns a message for every plugin or folder refused, one for every source file that gave no
// effect ("no effect from FILE:LINE:COLUMN: error: ..."), and one when no folder was found and
// PFX_PLUGIN_PATH is unset (then nothing can load).
std::vector<std::string> load_adapter_plugins(host::PluginRegistry& registry, const PluginFolderRule& rule);

}  // namespace pfx::adapters
