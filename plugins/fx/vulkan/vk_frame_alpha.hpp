#pragma once
// The frame's alpha put back into the picture before it leaves the technique: FX shaders use the
// back buffer's alpha as scratch (FXAA keeps luma there), and a frame's alpha is its own. One
// full-screen draw writes only the alpha of the target, texel by texel from the frame's copy. A
// caller whose frame's alpha means nothing (a swapchain composited opaque) skips it.
#include <vulkan/vulkan.h>

#include <string>

#include "vk_device.hpp"
#include "vk_images.hpp"

namespace pfx::fx::vulkan {

class FrameAlpha {
 public:
  // Draws `original`'s alpha into `target` (same size and format). Returns "" or what failed.
  std::string create(const Device& d, const Image& original, const Image& target, VkPipelineCache cache);
  void record(VkCommandBuffer commands, Image& original, Image& target);
  void destroy(const Device& d);

 private:
  const Device* d_ = nullptr;
  VkShaderModule modules_[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  int width_ = 1, height_ = 1;
};

}  // namespace pfx::fx::vulkan
