#pragma once
// Techniques an instance has replaced (its file was edited) while command buffers that use them
// may still run. Each is kept until the device has set an event recorded after the last frame
// that used it, which is asked without waiting (vkGetEventStatus), and destroyed then: the
// runtime never waits for the device, and an edit does not hold the old version's images for
// longer than the frames in flight. Whatever is left goes at destroy_all(), which the owner calls
// once every command buffer has completed.
#include <vulkan/vulkan.h>

#include <memory>
#include <vector>

#include "effect_compiler.hpp"
#include "vk_device.hpp"
#include "vk_technique.hpp"

namespace pfx::fx::vulkan {

class RetiredTechniques {
 public:
  RetiredTechniques() = default;
  RetiredTechniques(const RetiredTechniques&) = delete;
  RetiredTechniques& operator=(const RetiredTechniques&) = delete;
  ~RetiredTechniques() { destroy_all(); }

  // `technique` (built from `effect`) runs no more frames from now on.
  void retire(const Device& device, std::unique_ptr<Technique> technique, std::unique_ptr<CompiledEffect> effect);
  // At the end of a frame's commands: the event of each technique retired since the last frame.
  // Command buffers run in the order they were recorded, so once it is set, every frame that used
  // the technique has completed.
  void mark(VkCommandBuffer commands);
  // Destroys the techniques whose event the device has set. The event itself stays until
  // destroy_all(): the command buffer that set it may still be running, and an event may only go
  // once the commands that refer to it completed, which only the owner knows (one small object
  // an edit).
  void release_finished();
  void destroy_all();
  std::size_t count() const { return entries_.size(); }

 private:
  struct Entry {
    std::unique_ptr<Technique> technique;
    std::unique_ptr<CompiledEffect> effect;  // the model the technique points into
    VkEvent done = VK_NULL_HANDLE;           // none when it could not be made: kept until destroy_all()
    bool marked = false;                     // mark() recorded its event
  };
  const Device* d_ = nullptr;
  std::vector<Entry> entries_;
  std::vector<VkEvent> spent_;  // events set, whose technique went
};

}  // namespace pfx::fx::vulkan
