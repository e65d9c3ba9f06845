// Device memory for what the bridge makes itself (a go-between, a read-back buffer).
#pragma once

#include <string>

#include "vk_functions.hpp"

namespace pfx::vk {

// Allocates memory that fits `needs` from the first memory type with every property in `want`
// (`next` chained to the allocation); false with *error.
bool allocate_memory(const Functions& f, VkDevice device, VkPhysicalDevice physical_device,
                     const VkMemoryRequirements& needs, VkMemoryPropertyFlags want, const void* next,
                     VkDeviceMemory* memory, std::string* error);

// A buffer in host memory the CPU reads (cached where the device has such memory: it reads back
// at memory speed), mapped; false with *error and nothing left made.
struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};
bool make_host_buffer(const Functions& f, VkDevice device, VkPhysicalDevice physical_device, VkDeviceSize size,
                      HostBuffer* out, std::string* error);
void destroy_host_buffer(const Functions& f, VkDevice device, HostBuffer* buffer);

}  // namespace pfx::vk
