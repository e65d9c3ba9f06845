// pfx-inject is one launcher for OpenGL and Vulkan applications: beside preloading libpfxinject.so
// it enables pfx's Vulkan layer (host/adapters/vulkan), so whichever API the application presents
// with gets the chain. The layer is an implicit one the loader finds through its manifest; when the
// manifest lies beside pfx-inject (a build tree, or a prefix the loader does not search), that
// folder goes first in XDG_DATA_DIRS, where the loader looks for implicit layers.
#pragma once

#include <string>
#include <vector>

namespace pfx::inject {

// The variables that enable the layer, given the launcher's environment (NAME=VALUE strings, to
// which XDG_DATA_DIRS belongs); *replaced gets the name of a variable the result replaces.
std::vector<std::string> vulkan_layer_environment(const std::vector<std::string>& environment,
                                                  std::vector<std::string>* replaced);

}  // namespace pfx::inject
