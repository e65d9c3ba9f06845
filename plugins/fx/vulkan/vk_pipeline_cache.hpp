#pragma once
// The Vulkan pipeline cache of the FX runtime, kept on disk beside the GL program cache: one file
// per device in $XDG_CACHE_HOME/pfx/fx-vulkan (else ~/.cache/pfx/fx-vulkan), named by the
// device's vendor, device id, driver version and pipeline cache UUID, so a second start builds
// its pipelines from what the driver kept. A file whose checksum fails (damaged) or whose
// Vulkan header names another device or driver (stale) is ignored, and the cache starts empty
// and is written again. A file past 64 MiB starts over too (the cache only grows while it is
// used). Written under a temporary name and renamed. PFX_FX_CACHE=0 turns it off.
#include <vulkan/vulkan.h>

#include <string>

#include "vk_device.hpp"

namespace pfx::fx::vulkan {

class PipelineCacheFile {
 public:
  // Creates the VkPipelineCache from the device's file, or empty. Returns false (and leaves
  // handle() null) only when Vulkan refuses an empty cache.
  bool open(const Device& d);
  VkPipelineCache handle() const { return cache_; }
  // Writes the cache's data when it holds more than was read.
  void save();
  void destroy();
  const std::string& path() const { return path_; }
  bool loaded() const { return from_file_; }  // the cache started from the file

 private:
  const Device* d_ = nullptr;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
  std::string path_;
  std::size_t loaded_bytes_ = 0;  // what the file holds (read, or written since)
  bool from_file_ = false;
};

}  // namespace pfx::fx::vulkan
