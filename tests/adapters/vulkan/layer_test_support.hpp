// What the tests of pfx's Vulkan layer share: running an application that the sanitizer pass's
// layer goes into, finding lavapipe by name, and placing pfx's layer among explicit ones.
#pragma once

#include <string>
#include <vector>

#include "inject_run.hpp"

namespace pfx::test {

// The sanitizer pass (./run test) builds the layer with AddressSanitizer and the loader opens it in
// applications that are not: the runtime must then come first in the process (with the C++
// library after it, for C applications), and the application's and the drivers' own allocations
// are not ours to judge (pfx-inject's tests do the same with glxgears). Adds to an `env` command line (NAME=VALUE items); nothing in other builds.
void add_sanitizer_runtime(std::vector<std::string>* argv);

// The name of lavapipe's device, which mpv must be told: libplacebo passes over software devices
// unless one is named.
std::string lavapipe_device_name();

// pfx's layer through a manifest of the explicit kind in `folder`, so that VK_INSTANCE_LAYERS can
// place it among other layers (the loader puts every implicit layer above the explicit ones):
// with VK_LAYER_PATH=FOLDER and XDG_DATA_HOME=FOLDER (so the implicit one is not found too), it is
// VK_LAYER_PFX_post_effects.
void write_explicit_manifest(const ScratchFolder& folder);

}  // namespace pfx::test
