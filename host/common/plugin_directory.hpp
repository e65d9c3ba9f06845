// Where our programs look for plugins when --plugins is not given: build/plugins next to
// build/bin in a build tree, PREFIX/lib/pfx/plugins next to PREFIX/bin when installed.
#pragma once

#include <string>

namespace pfx::app {

// The folder of the running executable (from /proc/self/exe).
std::string executable_directory();
// The default plugin folder; empty when neither layout exists.
std::string default_plugin_directory();

}  // namespace pfx::app
