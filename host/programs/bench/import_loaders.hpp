// The three OBJ loaders the import benchmark compares, behind one call. tinyobjloader and assimp
// are used as their documentation says, with the options closest to what pfx's importer does:
// tinyobjloader triangulates (it does not deduplicate); assimp triangulates and joins identical
// vertices. Both run on one thread (neither has a multithreaded OBJ path).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>

namespace pfx::bench {

struct LoadCounts {
  bool ok = false;
  std::string error;
  uint64_t vertices = 0;   // as the loader reports them (tinyobjloader: positions, not deduplicated)
  uint64_t triangles = 0;
};

// Names of the loaders built into this pfx-bench ("pfx" always; the others when their packages
// were found at configure time).
std::vector<std::string> available_loaders();
bool loader_is_multithreaded(const std::string& name);
LoadCounts load_with(const std::string& name, const std::string& path, unsigned threads,
                     const pfx::host::PluginRegistry& registry);

}  // namespace pfx::bench
