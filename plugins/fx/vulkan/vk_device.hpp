#pragma once
// The Vulkan device an FX technique runs on, as its owner hands it over: the handles, and every
// function this runtime calls, loaded through the owner's vkGetInstanceProcAddr and
// vkGetDeviceProcAddr. A layer passes the next link of its chain, so the runtime calls the
// device below the layer and never the loader's trampolines; nothing here links to the loader.
// The runtime records commands and never submits, waits or creates a queue.
#include <vulkan/vulkan.h>

#include <string>

namespace pfx::fx::vulkan {

// Device-level functions, each a member of Device named as Vulkan names it.
#define PFX_VK_DEVICE_FUNCTIONS(X)                                                                                     \
  X(vkAllocateMemory) X(vkFreeMemory) X(vkCreateImage) X(vkDestroyImage) X(vkGetImageMemoryRequirements)             \
  X(vkBindImageMemory) X(vkCreateImageView) X(vkDestroyImageView) X(vkCreateBuffer) X(vkDestroyBuffer)               \
  X(vkGetBufferMemoryRequirements) X(vkBindBufferMemory) X(vkCreateSampler) X(vkDestroySampler)                      \
  X(vkCreateShaderModule) X(vkDestroyShaderModule) X(vkCreateDescriptorSetLayout) X(vkDestroyDescriptorSetLayout)    \
  X(vkCreateDescriptorPool) X(vkDestroyDescriptorPool) X(vkAllocateDescriptorSets) X(vkUpdateDescriptorSets)         \
  X(vkCreatePipelineLayout) X(vkDestroyPipelineLayout) X(vkCreateGraphicsPipelines) X(vkCreateComputePipelines)      \
  X(vkDestroyPipeline) X(vkCreateRenderPass) X(vkDestroyRenderPass) X(vkCreateFramebuffer) X(vkDestroyFramebuffer)   \
  X(vkCmdPipelineBarrier) X(vkCmdCopyImage) X(vkCmdBlitImage) X(vkCmdClearColorImage) X(vkCmdClearDepthStencilImage) X(vkCmdUpdateBuffer)           \
  X(vkCmdBeginRenderPass) X(vkCmdEndRenderPass) X(vkCmdBindPipeline) X(vkCmdBindDescriptorSets) X(vkCmdDraw)         \
  X(vkCmdDispatch) X(vkCmdCopyBufferToImage) X(vkMapMemory) X(vkUnmapMemory) X(vkCreatePipelineCache) X(vkDestroyPipelineCache) X(vkGetPipelineCacheData) \
  X(vkCreateEvent) X(vkDestroyEvent) X(vkGetEventStatus) X(vkCmdSetEvent)

struct Device {
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceProperties properties{};
  PFN_vkGetPhysicalDeviceFormatProperties vkGetPhysicalDeviceFormatProperties = nullptr;
#define PFX_VK_MEMBER(name) PFN_##name name = nullptr;
  PFX_VK_DEVICE_FUNCTIONS(PFX_VK_MEMBER)
#undef PFX_VK_MEMBER

  // Loads the functions and reads the physical device's properties. Returns "" or the name of a
  // function the device does not give.
  std::string load(PFN_vkGetInstanceProcAddr get_instance_proc, VkInstance instance, VkPhysicalDevice physical_device,
                   PFN_vkGetDeviceProcAddr get_device_proc, VkDevice logical_device);

  // Memory for `needs` with the `flags`, or VK_NULL_HANDLE.
  VkDeviceMemory allocate(const VkMemoryRequirements& needs, VkMemoryPropertyFlags flags) const;
  VkFormatFeatureFlags optimal_features(VkFormat format) const;
};

}  // namespace pfx::fx::vulkan
