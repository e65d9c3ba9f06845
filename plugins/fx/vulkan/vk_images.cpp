#include "vk_images.hpp"

#include "vk_states.hpp"

namespace pfx::fx::vulkan {
namespace {

constexpr VkAccessFlags kWrites = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT |
                                  VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

VkImageMemoryBarrier barrier(const Image& image, VkImageLayout layout, VkAccessFlags access, int first_level, int levels) {
  VkImageMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  b.srcAccessMask = image.access & kWrites;  // a read needs an execution dependency only
  b.dstAccessMask = access;
  b.oldLayout = image.layout;
  b.newLayout = layout;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.image;
  b.subresourceRange = {image.aspect, static_cast<std::uint32_t>(first_level), static_cast<std::uint32_t>(levels), 0, 1};
  return b;
}

VkImageView make_view(const Device& d, const Image& image, VkFormat format, int first_level, int levels, VkImageUsageFlags usage) {
  VkImageViewUsageCreateInfo restricted{};
  restricted.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO;
  restricted.usage = usage;
  VkImageViewCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  info.pNext = usage ? &restricted : nullptr;
  info.image = image.image;
  info.viewType = image.type == VK_IMAGE_TYPE_1D ? VK_IMAGE_VIEW_TYPE_1D : image.type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
  info.format = format;
  info.subresourceRange = {image.aspect, static_cast<std::uint32_t>(first_level), static_cast<std::uint32_t>(levels), 0, 1};
  VkImageView out = VK_NULL_HANDLE;
  return d.vkCreateImageView(d.device, &info, nullptr, &out) == VK_SUCCESS ? out : VK_NULL_HANDLE;
}

}  // namespace

VkFormat stencil_format(const Device& d) {
  for (VkFormat format : {VK_FORMAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT})
    if (d.optimal_features(format) & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
  return VK_FORMAT_UNDEFINED;
}

std::string create_image(const Device& d, const ImageShape& shape, Image& out) {
  out = Image{};
  out.type = shape.type;
  out.width = shape.width, out.height = shape.height, out.depth = shape.depth, out.levels = shape.levels;
  out.format = shape.format;
  out.srgb_format = srgb_form(shape.format);
  out.integer = shape.integer;
  if (shape.stencil)
    out.aspect = shape.format == VK_FORMAT_S8_UINT ? VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.flags = out.srgb_format != VK_FORMAT_UNDEFINED ? VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT : 0;
  info.imageType = shape.type;
  info.format = shape.format;
  info.extent = {static_cast<std::uint32_t>(shape.width), static_cast<std::uint32_t>(shape.height), static_cast<std::uint32_t>(shape.depth)};
  info.mipLevels = static_cast<std::uint32_t>(shape.levels);
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
               (shape.type != VK_IMAGE_TYPE_3D ? VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT : 0) | (shape.storage ? VK_IMAGE_USAGE_STORAGE_BIT : 0);
  if (shape.stencil) info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (d.vkCreateImage(d.device, &info, nullptr, &out.image) != VK_SUCCESS) return "vkCreateImage refused the texture's format or size";
  VkMemoryRequirements needs;
  d.vkGetImageMemoryRequirements(d.device, out.image, &needs);
  out.memory = d.allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!out.memory || d.vkBindImageMemory(d.device, out.image, out.memory, 0) != VK_SUCCESS) return "no device memory for a texture";
  out.view = make_view(d, out, out.format, 0, out.levels, 0);
  // The sRGB view is sampled and drawn into, never stored to: sRGB formats take no storage, so
  // the view of a storage texture says so (VkImageViewUsageCreateInfo, Vulkan 1.1).
  const VkImageUsageFlags srgb_usage = shape.storage ? info.usage & ~static_cast<VkImageUsageFlags>(VK_IMAGE_USAGE_STORAGE_BIT) : 0;
  if (out.srgb_format != VK_FORMAT_UNDEFINED) out.srgb_view = make_view(d, out, out.srgb_format, 0, out.levels, srgb_usage);
  if (!out.view || (out.srgb_format != VK_FORMAT_UNDEFINED && !out.srgb_view)) return "vkCreateImageView failed";
  return "";
}

void destroy_image(const Device& d, Image& image) {
  if (image.srgb_view) d.vkDestroyImageView(d.device, image.srgb_view, nullptr);
  if (image.view) d.vkDestroyImageView(d.device, image.view, nullptr);
  if (image.image) d.vkDestroyImage(d.device, image.image, nullptr);
  if (image.memory) d.vkFreeMemory(d.device, image.memory, nullptr);
  image = Image{};
}

VkImageView level_view(const Device& d, const Image& image, int level, VkFormat format) {
  return make_view(d, image, format, level, 1, format == image.format ? 0 : VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
}

void use_image(const Device& d, VkCommandBuffer commands, Image& image, VkImageLayout layout, VkAccessFlags access,
               VkPipelineStageFlags stage) {
  if (image.layout == layout && !(image.access & kWrites) && !(access & kWrites)) {
    image.access |= access;
    image.stage |= stage;
    return;
  }
  const VkImageMemoryBarrier b = barrier(image, layout, access, 0, image.levels);
  d.vkCmdPipelineBarrier(commands, image.stage, stage, 0, 0, nullptr, 0, nullptr, 1, &b);
  image.layout = layout;
  image.access = access;
  image.stage = stage;
}

void use_for_sampling(const Device& d, VkCommandBuffer commands, Image& image) {
  use_image(d, commands, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_SHADER_READ_BIT, kShaderStages);
}

void use_as_attachment(const Device& d, VkCommandBuffer commands, Image& image) {
  use_image(d, commands, image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
}

void use_as_storage(const Device& d, VkCommandBuffer commands, Image& image) {
  use_image(d, commands, image, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

void use_as_stencil(const Device& d, VkCommandBuffer commands, Image& image) {
  use_image(d, commands, image, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT);
}

void clear_image(const Device& d, VkCommandBuffer commands, Image& image, bool one) {
  use_image(d, commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  if (image.aspect != VK_IMAGE_ASPECT_COLOR_BIT) {
    const VkClearDepthStencilValue zero{1.0f, 0};
    const VkImageSubresourceRange range = {image.aspect, 0, 1, 0, 1};
    d.vkCmdClearDepthStencilImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    return;
  }
  VkClearColorValue value{};  // zero bits: 0 as a float, an int and a uint
  if (one) value.float32[0] = value.float32[1] = value.float32[2] = value.float32[3] = 1.0f;
  const VkImageSubresourceRange all = {VK_IMAGE_ASPECT_COLOR_BIT, 0, static_cast<std::uint32_t>(image.levels), 0, 1};
  d.vkCmdClearColorImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &all);
}

void generate_mips(const Device& d, VkCommandBuffer commands, Image& image) {
  if (image.levels <= 1) return;
  use_image(d, commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  const bool linear = !image.integer && (d.optimal_features(image.format) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
  auto extent = [&](int level) {
    auto half = [level](int size) { return static_cast<std::int32_t>(size >> level > 0 ? size >> level : 1); };
    return VkOffset3D{half(image.width), half(image.height), half(image.depth)};
  };
  for (int level = 1; level < image.levels; ++level) {
    // The level above was just written: make it the source.
    VkImageMemoryBarrier b = barrier(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT, level - 1, 1);
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    d.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<std::uint32_t>(level - 1), 0, 1};
    blit.srcOffsets[1] = extent(level - 1);
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<std::uint32_t>(level), 0, 1};
    blit.dstOffsets[1] = extent(level);
    d.vkCmdBlitImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                     linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
  }
  // Every level but the last is a source now, the last a destination: all of them to sampling.
  VkImageMemoryBarrier b[2] = {barrier(image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_SHADER_READ_BIT, 0, image.levels - 1),
                               barrier(image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_SHADER_READ_BIT, image.levels - 1, 1)};
  b[0].oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  b[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  b[1].srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  d.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, kShaderStages, 0, 0, nullptr, 0, nullptr, 2, b);
  image.layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  image.access = VK_ACCESS_SHADER_READ_BIT;
  image.stage = kShaderStages;
}

void copy_image(const Device& d, VkCommandBuffer commands, Image& from, Image& to) {
  use_image(d, commands, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  use_image(d, commands, to, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkImageCopy region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.extent = {static_cast<std::uint32_t>(from.width), static_cast<std::uint32_t>(from.height), static_cast<std::uint32_t>(from.depth)};
  d.vkCmdCopyImage(commands, from.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

}  // namespace pfx::fx::vulkan
