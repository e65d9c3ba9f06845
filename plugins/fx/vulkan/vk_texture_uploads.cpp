#include "vk_texture_uploads.hpp"

#include <cstring>

namespace pfx::fx::vulkan {

std::string TextureUploads::add(const Device& d, const Image& target, int target_index, const TextureTexels& texels) {
  d_ = &d;
  if (target.integer) return "an image file cannot fill a texture of integers";
  Upload upload;
  upload.target = target_index;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = texels.rgba.size();
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  if (d.vkCreateBuffer(d.device, &info, nullptr, &upload.buffer) != VK_SUCCESS) return "vkCreateBuffer failed";
  uploads_.push_back(upload);  // destroyed with the others from here on
  Upload& u = uploads_.back();
  VkMemoryRequirements needs;
  d.vkGetBufferMemoryRequirements(d.device, u.buffer, &needs);
  u.memory = d.allocate(needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  void* mapped = nullptr;
  if (!u.memory || d.vkBindBufferMemory(d.device, u.buffer, u.memory, 0) != VK_SUCCESS ||
      d.vkMapMemory(d.device, u.memory, 0, info.size, 0, &mapped) != VK_SUCCESS)
    return "no host memory for a texture's image";
  std::memcpy(mapped, texels.rgba.data(), texels.rgba.size());
  d.vkUnmapMemory(d.device, u.memory);
  if (target.format == VK_FORMAT_R8G8B8A8_UNORM) return "";
  ImageShape shape;
  shape.type = target.type;
  shape.width = target.width, shape.height = target.height, shape.depth = target.depth;
  shape.format = VK_FORMAT_R8G8B8A8_UNORM;
  const VkFormatFeatureFlags blit = VK_FORMAT_FEATURE_BLIT_SRC_BIT;
  if (!(d.optimal_features(target.format) & VK_FORMAT_FEATURE_BLIT_DST_BIT) || !(d.optimal_features(shape.format) & blit))
    return "the device cannot convert an image file's texels into the texture's format";
  return create_image(d, shape, u.staging);
}

void TextureUploads::record(VkCommandBuffer commands, std::vector<Image>& images) {
  if (recorded_) return;
  recorded_ = true;
  for (Upload& u : uploads_) {
    Image& target = images[static_cast<std::size_t>(u.target)];
    Image& first = u.staging.image ? u.staging : target;
    use_image(*d_, commands, first, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {static_cast<std::uint32_t>(first.width), static_cast<std::uint32_t>(first.height), static_cast<std::uint32_t>(first.depth)};
    d_->vkCmdCopyBufferToImage(commands, u.buffer, first.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    if (u.staging.image) {
      use_image(*d_, commands, u.staging, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      use_image(*d_, commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      VkImageBlit blit{};
      blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      blit.srcOffsets[1] = blit.dstOffsets[1] = {target.width, target.height, target.depth};
      d_->vkCmdBlitImage(commands, u.staging.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &blit, VK_FILTER_NEAREST);
    }
    generate_mips(*d_, commands, target);
    use_for_sampling(*d_, commands, target);
  }
}

void TextureUploads::destroy() {
  if (!d_) return;
  for (Upload& u : uploads_) {
    if (u.buffer) d_->vkDestroyBuffer(d_->device, u.buffer, nullptr);
    if (u.memory) d_->vkFreeMemory(d_->device, u.memory, nullptr);
    destroy_image(*d_, u.staging);
  }
  uploads_.clear();
  recorded_ = false;
  d_ = nullptr;
}

}  // namespace pfx::fx::vulkan
