// The command buffers the bridge's native path records frames into, each with a fence, used in
// turn. A buffer is recorded again only once the frame that last used it has completed; on a
// queue that keeps up that happened long before, so taking it costs no wait. waits() counts the
// times it had not: the application was then kSize frames ahead of the device, and waits as its
// own swapchain would make it wait.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <pfx/vulkan_bridge.h>

#include "vk_functions.hpp"
#include "vk_submit.hpp"

namespace pfx::vk {

class CommandRing {
 public:
  static constexpr uint32_t kSize = 4;

  CommandRing(const Functions& f, VkDevice device, VkQueue queue) : f_(f), device_(device), queue_(queue) {}
  ~CommandRing();  // after every submission completed
  CommandRing(const CommandRing&) = delete;
  CommandRing& operator=(const CommandRing&) = delete;

  // The pool, the buffers and their fences; set_loader_data as for Transport::init. False with *error.
  bool init(uint32_t queue_family_index, SetLoaderData set_loader_data, std::string* error);
  // The next buffer, begun (one-time submit). Null with *error.
  VkCommandBuffer begin(std::string* error);
  // Ends the buffer begin() gave and submits it: after the image's wait semaphores (at its stages,
  // else at every stage, since the effects' first use of the image may be any), signalling its
  // semaphore. False with *error: then nothing was submitted.
  bool submit(const pfx_vk_image& image, std::string* error);
  // Waits for the last submission (a read-back needs its bytes). False with *error.
  bool wait_last(std::string* error);
  // Waits for every submission.
  void wait_idle();
  uint64_t waits() const { return waits_; }

 private:
  struct Slot {
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    bool pending = false;
  };
  bool free_slot(Slot& slot, std::string* error);

  Functions f_;
  VkDevice device_;
  VkQueue queue_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::array<Slot, kSize> slots_{};
  uint32_t next_ = 0;     // the slot begin() takes
  uint32_t current_ = 0;  // the slot begin() took
  uint64_t waits_ = 0;
};

}  // namespace pfx::vk
