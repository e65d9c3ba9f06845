#include "vk_submit.hpp"

#include <vector>

namespace pfx::vk {

bool make_command_buffers(const Functions& f, VkDevice device, uint32_t queue_family_index,
                          SetLoaderData set_loader_data, uint32_t count, VkCommandPool* pool, VkCommandBuffer* buffers,
                          std::string* error) {
  VkCommandPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = queue_family_index;
  VkResult result = f.CreateCommandPool(device, &pool_info, nullptr, pool);
  if (result == VK_SUCCESS) {
    VkCommandBufferAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    info.commandPool = *pool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = count;
    result = f.AllocateCommandBuffers(device, &info, buffers);
  }
  for (uint32_t i = 0; result == VK_SUCCESS && set_loader_data && i < count; ++i)
    result = set_loader_data(device, buffers[i]);
  if (result != VK_SUCCESS) *error = "could not make the bridge's command buffers: " + result_name(result);
  return result == VK_SUCCESS;
}

bool submit_frame(const Functions& f, VkQueue queue, VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image,
                  VkPipelineStageFlags default_wait_stage, bool wait, bool signal, std::string* error) {
  std::vector<VkPipelineStageFlags> stages(image.wait_semaphore_count, default_wait_stage);
  if (image.wait_stages)
    for (uint32_t i = 0; i < image.wait_semaphore_count; ++i) stages[i] = image.wait_stages[i];
  VkSubmitInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  if (wait && image.wait_semaphore_count) {
    info.waitSemaphoreCount = image.wait_semaphore_count;
    info.pWaitSemaphores = image.wait_semaphores;
    info.pWaitDstStageMask = stages.data();
  }
  info.commandBufferCount = commands ? 1 : 0;
  info.pCommandBuffers = commands ? &commands : nullptr;
  if (signal && image.signal_semaphore) {
    info.signalSemaphoreCount = 1;
    info.pSignalSemaphores = &image.signal_semaphore;
  }
  const VkResult result = f.QueueSubmit(queue, 1, &info, fence);
  if (result != VK_SUCCESS) *error = "vkQueueSubmit failed: " + result_name(result);
  return result == VK_SUCCESS;
}

}  // namespace pfx::vk
