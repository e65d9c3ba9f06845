// The read-backs a native frame gives when its caller asks for them (pfx_vk_image's app_pixels
// and result_pixels, for captures and tests): the image copied into host memory before the
// effects and after them, in the same submission, and handed over as R, G, B, A bytes once it
// completed. Those frames, and only those, cost the CPU a wait.
#pragma once

#include <cstdint>
#include <string>

#include "vk_memory.hpp"

namespace pfx::vk {

class FrameReadback {
 public:
  FrameReadback(const Functions& f, VkDevice device, VkPhysicalDevice physical_device)
      : f_(f), device_(device), physical_device_(physical_device) {}
  ~FrameReadback() { destroy_host_buffer(f_, device_, &buffer_); }  // after the frames that used it
  FrameReadback(const FrameReadback&) = delete;
  FrameReadback& operator=(const FrameReadback&) = delete;

  // Room for two width x height frames of 32-bit texels; false with *error.
  bool prepare(uint32_t width, uint32_t height, std::string* error);
  // Records a copy of the image (in `layout` before and after) into the first half (before the
  // effects) or the second (after).
  void record(VkCommandBuffer commands, VkImage image, VkImageLayout layout, bool after);
  // Once the submission completed: each half that is asked for (not null) as R, G, B, A bytes,
  // row 0 the top row; bgra says the image's texels are B, G, R, A.
  void hand_over(bool bgra, uint8_t* before, uint8_t* after) const;

 private:
  Functions f_;
  VkDevice device_;
  VkPhysicalDevice physical_device_;
  HostBuffer buffer_;
  uint32_t width_ = 0, height_ = 0;
};

}  // namespace pfx::vk
