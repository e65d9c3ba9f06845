#include "vk_device.hpp"

namespace pfx::fx::vulkan {

std::string Device::load(PFN_vkGetInstanceProcAddr get_instance_proc, VkInstance instance, VkPhysicalDevice physical_device,
                         PFN_vkGetDeviceProcAddr get_device_proc, VkDevice logical_device) {
  physical = physical_device;
  device = logical_device;
  auto memory_properties = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties>(
      get_instance_proc(instance, "vkGetPhysicalDeviceMemoryProperties"));
  auto device_properties = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties>(get_instance_proc(instance, "vkGetPhysicalDeviceProperties"));
  vkGetPhysicalDeviceFormatProperties =
      reinterpret_cast<PFN_vkGetPhysicalDeviceFormatProperties>(get_instance_proc(instance, "vkGetPhysicalDeviceFormatProperties"));
  if (!memory_properties) return "vkGetPhysicalDeviceMemoryProperties";
  if (!device_properties) return "vkGetPhysicalDeviceProperties";
  if (!vkGetPhysicalDeviceFormatProperties) return "vkGetPhysicalDeviceFormatProperties";
  memory_properties(physical, &memory);
  device_properties(physical, &properties);
#define PFX_VK_LOAD(name)                                                          \
  name = reinterpret_cast<PFN_##name>(get_device_proc(device, #name));             \
  if (!name) return #name;
  PFX_VK_DEVICE_FUNCTIONS(PFX_VK_LOAD)
#undef PFX_VK_LOAD
  return "";
}

VkDeviceMemory Device::allocate(const VkMemoryRequirements& needs, VkMemoryPropertyFlags flags) const {
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = needs.size;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((needs.memoryTypeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
      info.memoryTypeIndex = i;
      VkDeviceMemory out = VK_NULL_HANDLE;
      return vkAllocateMemory(device, &info, nullptr, &out) == VK_SUCCESS ? out : VK_NULL_HANDLE;
    }
  return VK_NULL_HANDLE;
}

VkFormatFeatureFlags Device::optimal_features(VkFormat format) const {
  VkFormatProperties p{};
  vkGetPhysicalDeviceFormatProperties(physical, format, &p);
  return p.optimalTilingFeatures;
}

}  // namespace pfx::fx::vulkan
