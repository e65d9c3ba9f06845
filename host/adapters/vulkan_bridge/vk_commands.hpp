// Small pieces every command buffer of the bridge is recorded with: an image barrier over every
// layer of a colour image, and the begin info of a buffer submitted once.
#pragma once

#include <vulkan/vulkan.h>

namespace pfx::vk {

constexpr VkAccessFlags kAnyAccess = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;

inline VkImageMemoryBarrier barrier_for(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src_access,
                                        VkAccessFlags dst_access) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  // Every layer: the caller's image has one, the go-between one or two.
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
  return barrier;
}

inline VkCommandBufferBeginInfo one_time() {
  VkCommandBufferBeginInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  return info;
}

}  // namespace pfx::vk
