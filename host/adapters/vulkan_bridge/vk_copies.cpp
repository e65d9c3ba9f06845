// The two submissions of a frame (vk_transport.hpp): in, and back out.
#include "vk_transport.hpp"

#include <algorithm>

#include "vk_commands.hpp"

namespace pfx::vk {

void Transport::record_blit(VkCommandBuffer commands, const pfx_vk_image& image, bool into_between) {
  // Layer 0 is what the chain samples, layer 1 what it draws. The image's top row meets the
  // layer's last, which GL takes for the top of the picture.
  const int32_t width = int32_t(width_), height = int32_t(height_);
  const VkOffset3D top_first[2] = {{0, 0, 0}, {width, height, 1}};
  const VkOffset3D bottom_first[2] = {{0, height, 0}, {width, 0, 1}};
  const VkImageSubresourceLayers image_layer{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  VkImageBlit region{};
  if (into_between) {
    region.srcSubresource = image_layer;
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    std::copy(top_first, top_first + 2, region.srcOffsets);
    std::copy(bottom_first, bottom_first + 2, region.dstOffsets);
    f_.CmdBlitImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, between_image_,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  } else {
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 1};
    region.dstSubresource = image_layer;
    std::copy(bottom_first, bottom_first + 2, region.srcOffsets);
    std::copy(top_first, top_first + 2, region.dstOffsets);
    f_.CmdBlitImage(commands, between_image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  }
}

void Transport::record_copy_in(VkCommandBuffer commands, const pfx_vk_image& image) {
  // Between submissions the go-between is in GENERAL: the GL side reads and writes it then, and
  // without shared semaphores there is no way to hand a layout over. Each copy takes it to the
  // transfer layout the copy wants and back.
  const VkImageLayout between_from = between_fresh_ ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_GENERAL;
  VkImageMemoryBarrier before[2] = {
      barrier_for(image.image, image.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_MEMORY_WRITE_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT),
      barrier_for(between_image_, between_from, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kAnyAccess,
                  VK_ACCESS_TRANSFER_WRITE_BIT)};
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr,
                        0, nullptr, between_image_ ? 2 : 1, before);
  between_fresh_ = false;
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  if (between_.blits) {
    record_blit(commands, image, true);
  } else if (between_image_) {
    // A raw copy: B8G8R8A8 and R8G8B8A8, UNORM or SRGB, and A2B10G10R10 and A2R10G10B10 are all
    // 32-bit texels; the GL side reads them as what they are, swizzles and decodes.
    VkImageCopy region{};
    region.srcSubresource = layers;
    region.dstSubresource = layers;
    region.extent = {width_, height_, 1};
    f_.CmdCopyImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, between_image_,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else {
    VkBufferImageCopy region{};  // rows tightly packed, row 0 the image's top row
    region.imageSubresource = layers;
    region.imageExtent = {width_, height_, 1};
    f_.CmdCopyImageToBuffer(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, between_buffer_, 1,
                            &region);
  }
  // The copy's writes made available to the host, and to the GL reading the same memory; the
  // go-between back in GENERAL for it.
  VkMemoryBarrier after{};
  after.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_MEMORY_READ_BIT;
  const VkImageMemoryBarrier to_general =
      barrier_for(between_image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_MEMORY_READ_BIT);
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 1, &after, 0, nullptr,
                        between_image_ ? 1 : 0, &to_general);
}

bool Transport::copy_in(const pfx_vk_image& image, std::string* error) {
  wait_idle();
  f_.ResetCommandBuffer(in_, 0);
  const VkCommandBufferBeginInfo begin = one_time();
  VkResult result = f_.BeginCommandBuffer(in_, &begin);
  if (result == VK_SUCCESS) {
    record_copy_in(in_, image);
    result = f_.EndCommandBuffer(in_);
  }
  if (result != VK_SUCCESS) {
    *error = "could not record the copy in: " + result_name(result);
    return false;
  }
  if (!submit(in_, in_done_, image, true, false, error)) return false;
  result = f_.WaitForFences(device_, 1, &in_done_, VK_TRUE, UINT64_MAX);
  f_.ResetFences(device_, 1, &in_done_);
  if (result != VK_SUCCESS) *error = "waiting for the copy in failed: " + result_name(result);
  return result == VK_SUCCESS;
}

void Transport::record_copy_back(VkCommandBuffer commands, const pfx_vk_image& image) {
  // The GL's (or the host's) writes to the go-between finished before this submission.
  VkMemoryBarrier between{};
  between.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  between.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  between.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  const VkImageMemoryBarrier before[2] = {
      barrier_for(image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                  VK_ACCESS_TRANSFER_WRITE_BIT),
      barrier_for(between_image_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_MEMORY_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT)};
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &between, 0, nullptr, between_image_ ? 2 : 1, before);
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  if (between_.blits) {
    record_blit(commands, image, false);
  } else if (between_image_) {
    VkImageCopy region{};
    region.srcSubresource = layers;
    region.dstSubresource = layers;
    region.extent = {width_, height_, 1};
    f_.CmdCopyImage(commands, between_image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else {
    VkBufferImageCopy region{};
    region.imageSubresource = layers;
    region.imageExtent = {width_, height_, 1};
    f_.CmdCopyBufferToImage(commands, between_buffer_, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                            &region);
  }
  // The image back to its layout; the go-between to GENERAL, where the GL finds it next.
  const VkImageMemoryBarrier after[2] = {
      barrier_for(image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, image.layout, VK_ACCESS_TRANSFER_WRITE_BIT,
                  kAnyAccess),
      barrier_for(between_image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, 0, kAnyAccess)};
  f_.CmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr,
                        0, nullptr, between_image_ ? 2 : 1, after);
}

bool Transport::copy_out(const pfx_vk_image& image, bool copy_back, std::string* error) {
  wait_idle();  // the command buffer and fence are free again (copy_in waited already)
  f_.ResetCommandBuffer(out_, 0);
  const VkCommandBufferBeginInfo begin = one_time();
  VkResult result = f_.BeginCommandBuffer(out_, &begin);
  if (result == VK_SUCCESS) {
    if (copy_back) {
      record_copy_back(out_, image);
    } else {
      VkImageMemoryBarrier back =
          barrier_for(image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.layout, 0, kAnyAccess);
      f_.CmdPipelineBarrier(out_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                            nullptr, 1, &back);
    }
    result = f_.EndCommandBuffer(out_);
  }
  if (result != VK_SUCCESS) {
    *error = "could not record the copy back: " + result_name(result);
    return false;
  }
  // The go-between is used again only after this copy back completed.
  if (!submit(out_, out_done_, image, false, true, error)) return false;
  out_pending_ = true;
  return true;
}

}  // namespace pfx::vk
