#include "frame_readback.hpp"

#include <cstring>

#include "vk_commands.hpp"

namespace pfx::vk {

bool FrameReadback::prepare(uint32_t width, uint32_t height, std::string* error) {
  if (buffer_.buffer && width == width_ && height == height_) return true;
  destroy_host_buffer(f_, device_, &buffer_);
  width_ = height_ = 0;
  if (!make_host_buffer(f_, device_, physical_device_, VkDeviceSize(width) * height * 4 * 2, &buffer_, error))
    return false;
  width_ = width;
  height_ = height;
  return true;
}

void FrameReadback::record(VkCommandBuffer commands, VkImage image, VkImageLayout layout, bool after) {
  // Whatever wrote the image before (the application, or the effects) is done first.
  const VkImageMemoryBarrier to_copy = barrier_for(image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                                   VK_ACCESS_MEMORY_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                        nullptr, 1, &to_copy);
  VkBufferImageCopy region{};  // rows tightly packed, row 0 the image's top row
  region.bufferOffset = after ? VkDeviceSize(width_) * height_ * 4 : 0;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width_, height_, 1};
  f_.CmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_.buffer, 1, &region);
  const VkImageMemoryBarrier back = barrier_for(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, 0, kAnyAccess);
  VkMemoryBarrier to_host{};
  to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 1,
                        &back);
}

void FrameReadback::hand_over(bool bgra, uint8_t* before, uint8_t* after) const {
  const size_t bytes = size_t(width_) * height_ * 4;
  const auto* mapped = static_cast<const uint8_t*>(buffer_.mapped);
  uint8_t* const halves[2] = {before, after};
  for (int half = 0; half < 2; ++half) {
    uint8_t* out = halves[half];
    if (!out) continue;
    std::memcpy(out, mapped + half * bytes, bytes);
    if (bgra)
      for (size_t i = 0; i < bytes; i += 4) std::swap(out[i], out[i + 2]);
  }
}

}  // namespace pfx::vk
