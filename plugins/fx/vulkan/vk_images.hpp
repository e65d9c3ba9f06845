#pragma once
// The images of an FX technique on Vulkan, each with the layout and the last access the recorded
// commands left it in, so that every use is preceded by the barrier it needs and no other:
// sampled (read-only layout), drawn into (attachment), stored to (general), copied, cleared, or
// reduced to its mip levels. Commands recorded for one frame assume those of the frame before
// ran first, on the same queue (the order a layer's present or a host's frame loop gives).
#include <vulkan/vulkan.h>

#include <string>

#include "vk_device.hpp"

namespace pfx::fx::vulkan {

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;       // every level, in the image's format
  VkImageView srgb_view = VK_NULL_HANDLE;  // the sRGB form, where the format has one
  VkFormat format = VK_FORMAT_UNDEFINED, srgb_format = VK_FORMAT_UNDEFINED;
  VkImageType type = VK_IMAGE_TYPE_2D;
  int width = 1, height = 1, depth = 1, levels = 1;
  bool integer = false;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;  // depth and stencil for the stencil buffer
  // What the recorded commands leave it in.
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkAccessFlags access = 0;
  VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
};

struct ImageShape {
  VkImageType type = VK_IMAGE_TYPE_2D;
  int width = 1, height = 1, depth = 1, levels = 1;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  bool integer = false;
  bool storage = false;  // a compute pass stores to it
  // The stencil buffer: a depth-stencil attachment (`format` has a stencil aspect), cleared by
  // copy commands, never sampled.
  bool stencil = false;
};

// A stencil format the device draws with: 8-bit stencil alone where it can, else with depth.
VkFormat stencil_format(const Device& d);

// Device-local storage of the shape, usable as a sampled image, colour attachment and copy source
// and destination (and storage image when asked); an sRGB view where the format has an sRGB form.
// Returns "" or what failed.
std::string create_image(const Device& d, const ImageShape& shape, Image& out);
void destroy_image(const Device& d, Image& image);
// A view of one level in `format` (a storage's mip level, a render target's level 0); the caller
// destroys it.
VkImageView level_view(const Device& d, const Image& image, int level, VkFormat format);

// Barrier helpers over the tracked state.
constexpr VkPipelineStageFlags kShaderStages =
    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
// Brings every level of `image` into `layout` for an access at `stage`. Reads after reads in the
// same layout need no barrier; they are gathered so the next write waits for all of them.
void use_image(const Device& d, VkCommandBuffer commands, Image& image, VkImageLayout layout, VkAccessFlags access,
               VkPipelineStageFlags stage);
void use_for_sampling(const Device& d, VkCommandBuffer commands, Image& image);
void use_as_attachment(const Device& d, VkCommandBuffer commands, Image& image);
void use_as_storage(const Device& d, VkCommandBuffer commands, Image& image);
void use_as_stencil(const Device& d, VkCommandBuffer commands, Image& image);

// Every level filled with zeros (`one`: with 1.0, the far plane of a depth texture); a stencil
// buffer with stencil 0.
void clear_image(const Device& d, VkCommandBuffer commands, Image& image, bool one = false);
// Level 0 to every other level, each halving the last (linear filtering where the format allows
// it), as GenerateMipMaps asks; the image is ready to sample afterwards.
void generate_mips(const Device& d, VkCommandBuffer commands, Image& image);
// The whole of level 0 of `from` into `to` (same size, formats of one size class).
void copy_image(const Device& d, VkCommandBuffer commands, Image& from, Image& to);

}  // namespace pfx::fx::vulkan
