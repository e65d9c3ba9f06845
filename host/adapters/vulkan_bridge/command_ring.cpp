#include "command_ring.hpp"

#include "vk_commands.hpp"
#include "vk_submit.hpp"

namespace pfx::vk {

CommandRing::~CommandRing() {
  wait_idle();
  for (Slot& slot : slots_)
    if (slot.done) f_.DestroyFence(device_, slot.done, nullptr);
  if (pool_) f_.DestroyCommandPool(device_, pool_, nullptr);  // frees its command buffers
}

bool CommandRing::init(uint32_t queue_family_index, SetLoaderData set_loader_data, std::string* error) {
  VkCommandBuffer buffers[kSize] = {};
  if (!make_command_buffers(f_, device_, queue_family_index, set_loader_data, kSize, &pool_, buffers, error))
    return false;
  VkFenceCreateInfo fence_info{};
  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkResult result = VK_SUCCESS;
  for (uint32_t i = 0; i < kSize && result == VK_SUCCESS; ++i) {
    slots_[i].commands = buffers[i];
    result = f_.CreateFence(device_, &fence_info, nullptr, &slots_[i].done);
  }
  if (result != VK_SUCCESS) *error = "could not make the bridge's fences: " + result_name(result);
  return result == VK_SUCCESS;
}

bool CommandRing::free_slot(Slot& slot, std::string* error) {
  if (!slot.pending) return true;
  VkResult result = f_.GetFenceStatus(device_, slot.done);
  if (result == VK_NOT_READY) {
    ++waits_;
    result = f_.WaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX);
  }
  if (result != VK_SUCCESS) {
    *error = "waiting for an earlier frame failed: " + result_name(result);
    return false;
  }
  f_.ResetFences(device_, 1, &slot.done);
  slot.pending = false;
  return true;
}

VkCommandBuffer CommandRing::begin(std::string* error) {
  Slot& slot = slots_[next_];
  if (!free_slot(slot, error)) return VK_NULL_HANDLE;
  f_.ResetCommandBuffer(slot.commands, 0);
  const VkCommandBufferBeginInfo info = one_time();
  const VkResult result = f_.BeginCommandBuffer(slot.commands, &info);
  if (result != VK_SUCCESS) {
    *error = "could not begin a command buffer: " + result_name(result);
    return VK_NULL_HANDLE;
  }
  current_ = next_;
  next_ = (next_ + 1) % kSize;
  return slot.commands;
}

bool CommandRing::submit(const pfx_vk_image& image, std::string* error) {
  Slot& slot = slots_[current_];
  const VkResult result = f_.EndCommandBuffer(slot.commands);
  if (result != VK_SUCCESS) {
    *error = "could not record the frame's commands: " + result_name(result);
    return false;
  }
  if (!submit_frame(f_, queue_, slot.commands, slot.done, image, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, true, true, error))
    return false;
  slot.pending = true;
  return true;
}

bool CommandRing::wait_last(std::string* error) {
  Slot& slot = slots_[current_];
  if (!slot.pending) return true;
  const VkResult result = f_.WaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX);
  if (result != VK_SUCCESS) *error = "waiting for the frame failed: " + result_name(result);
  return result == VK_SUCCESS;
}

void CommandRing::wait_idle() {
  // Not a frame's wait (waits() counts those): the bridge is resized or going.
  for (Slot& slot : slots_) {
    if (!slot.pending) continue;
    f_.WaitForFences(device_, 1, &slot.done, VK_TRUE, UINT64_MAX);
    f_.ResetFences(device_, 1, &slot.done);
    slot.pending = false;
  }
}

}  // namespace pfx::vk
