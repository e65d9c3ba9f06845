#include "vk_memory.hpp"

namespace pfx::vk {

bool allocate_memory(const Functions& f, VkDevice device, VkPhysicalDevice physical_device,
                     const VkMemoryRequirements& needs, VkMemoryPropertyFlags want, const void* next,
                     VkDeviceMemory* memory, std::string* error) {
  VkPhysicalDeviceMemoryProperties properties{};
  f.GetPhysicalDeviceMemoryProperties(physical_device, &properties);
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
    if (!(needs.memoryTypeBits & (1u << i)) || (properties.memoryTypes[i].propertyFlags & want) != want) continue;
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.pNext = next;
    info.allocationSize = needs.size;
    info.memoryTypeIndex = i;
    const VkResult result = f.AllocateMemory(device, &info, nullptr, memory);
    if (result == VK_SUCCESS) return true;
    *error = "could not allocate the bridge's memory: " + result_name(result);
    return false;
  }
  *error = "no Vulkan memory type fits the bridge's buffer";
  return false;
}

bool make_host_buffer(const Functions& f, VkDevice device, VkPhysicalDevice physical_device, VkDeviceSize size,
                      HostBuffer* out, std::string* error) {
  HostBuffer made;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkResult result = f.CreateBuffer(device, &info, nullptr, &made.buffer);
  if (result != VK_SUCCESS) {
    *error = "could not make the host-memory buffer: " + result_name(result);
    return false;
  }
  VkMemoryRequirements needs{};
  f.GetBufferMemoryRequirements(device, made.buffer, &needs);
  const VkMemoryPropertyFlags visible = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  // Cached memory reads back at memory speed; uncached is a fallback every device has.
  if (!allocate_memory(f, device, physical_device, needs, visible | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, nullptr,
                       &made.memory, error) &&
      !allocate_memory(f, device, physical_device, needs, visible, nullptr, &made.memory, error)) {
    destroy_host_buffer(f, device, &made);
    return false;
  }
  result = f.BindBufferMemory(device, made.buffer, made.memory, 0);
  if (result == VK_SUCCESS) result = f.MapMemory(device, made.memory, 0, VK_WHOLE_SIZE, 0, &made.mapped);
  if (result != VK_SUCCESS) {
    *error = "could not map the host-memory buffer: " + result_name(result);
    destroy_host_buffer(f, device, &made);
    return false;
  }
  *out = made;
  return true;
}

void destroy_host_buffer(const Functions& f, VkDevice device, HostBuffer* buffer) {
  if (buffer->mapped) f.UnmapMemory(device, buffer->memory);
  if (buffer->buffer) f.DestroyBuffer(device, buffer->buffer, nullptr);
  if (buffer->memory) f.FreeMemory(device, buffer->memory, nullptr);
  *buffer = HostBuffer{};
}

}  // namespace pfx::vk
