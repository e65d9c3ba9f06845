#pragma once
// Textures that start from an image file (`source =`): the decoded 8-bit texels wait in a
// host-visible buffer and reach the texture in the first frame's commands, after the textures are
// cleared: copied straight into an RGBA8 texture, or into an RGBA8 image and blitted into one of
// another format (the GPU converts the codes as GL converts an RGBA upload); then the mip levels
// are made. The buffers stay until the technique is destroyed: the first frame may still be
// reading them when record() returns.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "texture_image.hpp"
#include "vk_device.hpp"
#include "vk_images.hpp"

namespace pfx::fx::vulkan {

class TextureUploads {
 public:
  // Texels for `target` (the texture's image, at the texels' size). Returns "" or what failed.
  std::string add(const Device& d, const Image& target, int target_index, const TextureTexels& texels);
  // The copies into `images` (indexed as add() was told), once.
  void record(VkCommandBuffer commands, std::vector<Image>& images);
  void destroy();

 private:
  struct Upload {
    int target = -1;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    Image staging;  // RGBA8, for a texture of another format
  };
  const Device* d_ = nullptr;
  std::vector<Upload> uploads_;
  bool recorded_ = false;
};

}  // namespace pfx::fx::vulkan
