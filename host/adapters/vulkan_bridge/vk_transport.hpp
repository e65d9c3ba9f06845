// The Vulkan half of a frame's trip through the bridge: the caller's image is copied into a
// go-between the GL side can read (an image whose memory GL imports, or a buffer in host memory),
// and the GL side's result copied back from it. Ordered by waiting: copy_in waits for its fence
// before the GL reads; copy_out is waited for before the go-between is used again.
//
// A shared go-between of an 8-bit image is two R8G8B8A8 layers that blits fill and empty: a blit
// turns the rows over into GL's bottom-row-first order and puts the channels in R, G, B, A order
// (a copy can do neither), so the chain samples layer 0 and draws layer 1 as they are, and the GL
// side adds no copy of its own. Otherwise (10-bit images, whose two extra bits an 8-bit layer
// would lose; a device that cannot blit the format; host memory) the go-between holds the image's
// bits as they are, and the GL side turns, swaps and decodes them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/vulkan_bridge.h>

#include "vk_functions.hpp"
#include "vk_submit.hpp"

namespace pfx::vk {

enum class Path { SHARED, HOST };

// The formats the bridge takes: 8-bit R8G8B8A8 and B8G8R8A8, UNORM or SRGB; 10-bit A2B10G10R10 and
// A2R10G10B10.
bool is_eight_bit(VkFormat format);
bool is_ten_bit(VkFormat format);

// What the go-between holds.
struct Between {
  bool blits = false;    // two R8G8B8A8 layers filled and emptied by blits (above)
  bool srgb = false;     // with blits: the layers are R8G8B8A8_SRGB, as the image's format is sRGB, so the
                         // blit converts nothing (between UNORM formats it converts nothing either)
  bool ten_bit = false;  // without: 10-bit RGB with 2-bit alpha, else 8-bit RGBA (or BGRA) texels
  bool operator==(const Between& other) const {
    return blits == other.blits && srgb == other.srgb && ten_bit == other.ten_bit;
  }
};

class Transport {
 public:
  Transport(const Functions& f, VkDevice device, VkPhysicalDevice physical_device, VkQueue queue)
      : f_(f), device_(device), physical_device_(physical_device), queue_(queue) {}
  ~Transport();
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;

  // The command pool, its two command buffers and fences; false with *error. set_loader_data,
  // when not null, is called on each command buffer (pfx_vk_bridge_desc says why).
  bool init(uint32_t queue_family_index, SetLoaderData set_loader_data, std::string* error);

  // The go-between for an image of the format (one the bridge takes) on the path: blits only where
  // the path is SHARED, the image is 8-bit, and the device can blit both formats both ways (asked
  // once, by init).
  Between between_for(Path path, VkFormat format) const;
  // Makes the go-between for a width x height frame: SHARED, an exportable image whose memory
  // *fd (a new descriptor the caller owns) and *memory_size describe; HOST, a mapped buffer
  // (mapped()). A new go-between goes with a new reading on the GL side. Waits for work in flight
  // first. When it is already that, a no-op with *fd = -1.
  bool prepare(Path path, uint32_t width, uint32_t height, Between between, int* fd, uint64_t* memory_size,
               std::string* error);
  bool prepared(Path path, uint32_t width, uint32_t height, Between between) const;
  Between between() const { return between_; }
  void* mapped() const { return mapped_; }
  uint64_t row_bytes() const { return uint64_t(width_) * 4; }

  // Waits on the image's semaphores, copies the image into the go-between and waits for that.
  // On failure nothing was submitted (the semaphores are still to be waited on).
  bool copy_in(const pfx_vk_image& image, std::string* error);
  // After copy_in: copies the go-between back into the image when copy_back (else leaves the image
  // as it was), returns the image to its layout and signals its semaphore.
  bool copy_out(const pfx_vk_image& image, bool copy_back, std::string* error);
  // Waits for the last copy_out.
  void wait_idle();

 private:
  bool make_shared_image(std::string* error);
  bool make_host_buffer(std::string* error);
  void release_between();
  bool submit(VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image, bool wait, bool signal,
              std::string* error);
  void record_copy_in(VkCommandBuffer commands, const pfx_vk_image& image);
  void record_copy_back(VkCommandBuffer commands, const pfx_vk_image& image);
  // A blit between the image and the go-between's layer that turns the rows over.
  void record_blit(VkCommandBuffer commands, const pfx_vk_image& image, bool into_between);
  bool can_blit(VkFormat format) const;

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
  std::vector<VkFormat> blit_formats_;  // the 8-bit formats that go by blits (init)
  Between between_;
  VkImage between_image_ = VK_NULL_HANDLE;
  bool between_fresh_ = false;  // the image was never used: its layout is still UNDEFINED
  VkBuffer between_buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

}  // namespace pfx::vk
