#include "vk_pipeline_cache.hpp"

#include <cstdio>
#include <cstring>
#include <vector>

#include <pfx/cpp/cache_files.hpp>

namespace pfx::fx::vulkan {
namespace {

constexpr char kMagic[8] = {'P', 'F', 'X', 'V', 'K', 'P', 'C', '1'};
constexpr std::size_t kMaxBytes = 64u << 20;

// Whether data that Vulkan gave names this device (VkPipelineCacheHeaderVersionOne: length,
// version, vendor, device, UUID). A driver checks it too; checking first keeps another device's
// data away from a driver that would not.
bool names_device(const std::string& data, const VkPhysicalDeviceProperties& p) {
  if (data.size() < 32) return false;
  std::uint32_t words[4];
  std::memcpy(words, data.data(), 16);
  return words[0] >= 32 && words[1] == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && words[2] == p.vendorID && words[3] == p.deviceID &&
         std::memcmp(data.data() + 16, p.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

}  // namespace

bool PipelineCacheFile::open(const Device& d) {
  d_ = &d;
  const VkPhysicalDeviceProperties& p = d.properties;
  const std::string folder = pfx::cache::folder_for("fx-vulkan", "PFX_FX_CACHE");
  std::string data;
  if (!folder.empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "%08x-%08x-%08x-", p.vendorID, p.deviceID, p.driverVersion);
    path_ = folder + "/" + name;
    for (std::uint8_t byte : p.pipelineCacheUUID) {
      char hex[3];
      std::snprintf(hex, sizeof hex, "%02x", byte);
      path_ += hex;
    }
    path_ += ".bin";
    if (!pfx::cache::read_checked(path_, kMagic, data) || !names_device(data, p) || data.size() > kMaxBytes) data.clear();
  }
  VkPipelineCacheCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  if (d.vkCreatePipelineCache(d.device, &info, nullptr, &cache_) != VK_SUCCESS) {
    info.initialDataSize = 0, info.pInitialData = nullptr;  // a driver that refuses the data
    data.clear();
    if (d.vkCreatePipelineCache(d.device, &info, nullptr, &cache_) != VK_SUCCESS) return false;
  }
  loaded_bytes_ = data.size();
  from_file_ = !data.empty();
  return true;
}

void PipelineCacheFile::save() {
  if (!cache_ || path_.empty()) return;
  std::size_t size = 0;
  if (d_->vkGetPipelineCacheData(d_->device, cache_, &size, nullptr) != VK_SUCCESS || size == 0 || size <= loaded_bytes_) return;
  std::string data(size, '\0');
  if (d_->vkGetPipelineCacheData(d_->device, cache_, &size, data.data()) != VK_SUCCESS) return;
  data.resize(size);
  if (pfx::cache::write_checked(path_, kMagic, data)) loaded_bytes_ = size;
}

void PipelineCacheFile::destroy() {
  if (cache_) d_->vkDestroyPipelineCache(d_->device, cache_, nullptr);
  cache_ = VK_NULL_HANDLE;
  loaded_bytes_ = 0;
  from_file_ = false;
}

}  // namespace pfx::fx::vulkan
