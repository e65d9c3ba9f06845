// The Vulkan half of a frame's trip through the bridge: the caller's image is copied into a
// go-between the GL side can read (an image whose memory GL imports, or a buffer in host memory),
// and the GL side's result copied back from it. Ordered by waiting: copy_in waits for its fence
// before the GL reads; copy_out is waited for before the go-between is used again.
#pragma once

#include <cstdint>
#include <string>

#include <pfx/vulkan_bridge.h>

#include "vk_functions.hpp"

namespace pfx::vk {

enum class Path { SHARED, HOST };

class Transport {
 public:
  Transport(const Functions& f, VkDevice device, VkPhysicalDevice physical_device, VkQueue queue)
      : f_(f), device_(device), physical_device_(physical_device), queue_(queue) {}
  ~Transport();
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;

  // The command pool, its two command buffers and fences; false with *error. set_loader_data,
  // when not null, is called on each command buffer (pfx_vk_bridge_desc says why).
  using SetLoaderData = VkResult(VKAPI_PTR*)(VkDevice, void*);
  bool init(uint32_t queue_family_index, SetLoaderData set_loader_data, std::string* error);

  // Makes the go-between for a width x height frame of 32-bit texels (8-bit RGBA, or 10-bit RGB
  // with 2-bit alpha when ten_bit: the GL side reads the same bytes either way, and a new
  // go-between goes with a new reading): SHARED, an exportable image whose memory *fd (a new
  // descriptor the caller owns) and *memory_size describe; HOST, a mapped buffer (mapped()).
  // Waits for work in flight first. When it is already that, a no-op with *fd = -1.
  bool prepare(Path path, uint32_t width, uint32_t height, bool ten_bit, int* fd, uint64_t* memory_size,
               std::string* error);
  bool prepared(Path path, uint32_t width, uint32_t height, bool ten_bit) const;
  void* mapped() const { return mapped_; }
  uint64_t row_bytes() const { return uint64_t(width_) * 4; }

  // Waits on the image's semaphores, copies the image into the go-between and waits for that.
  // On failure nothing was submitted (the semaphores are still to be waited on).
  bool copy_in(const pfx_vk_image& image, std::string* error);
  // After copy_in: copies the go-between back into the image when copy_back (else leaves the image
  // as it was), returns the image to its layout and signals its semaphore. Without a copy_in
  // before it (copied_in false) it only waits on the image's semaphores and signals its own.
  bool copy_out(const pfx_vk_image& image, bool copied_in, bool copy_back, std::string* error);
  // Waits for the last copy_out.
  void wait_idle();

 private:
  bool make_shared_image(std::string* error);
  bool make_host_buffer(std::string* error);
  bool allocate(const VkMemoryRequirements& needs, VkMemoryPropertyFlags want, const void* next,
                VkDeviceMemory* memory, std::string* error);
  void release_between();
  bool submit(VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image, bool wait, bool signal,
              std::string* error);
  void record_copy_in(VkCommandBuffer commands, const pfx_vk_image& image);
  void record_copy_back(VkCommandBuffer commands, const pfx_vk_image& image);

  Functions f_;
  VkDevice device_;
  VkPhysicalDevice physical_device_;
  VkQueue queue_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer in_ = VK_NULL_HANDLE, out_ = VK_NULL_HANDLE;
  VkFence in_done_ = VK_NULL_HANDLE, out_done_ = VK_NULL_HANDLE;
  bool out_pending_ = false;
  Path path_ = Path::HOST;
  uint32_t width_ = 0, height_ = 0;
  bool ten_bit_ = false;
  VkImage between_image_ = VK_NULL_HANDLE;
  bool between_fresh_ = false;  // the image was never used: its layout is still UNDEFINED
  VkBuffer between_buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

}  // namespace pfx::vk
