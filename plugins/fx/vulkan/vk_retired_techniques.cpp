#include "vk_retired_techniques.hpp"

namespace pfx::fx::vulkan {

void RetiredTechniques::retire(const Device& device, std::unique_ptr<Technique> technique,
                               std::unique_ptr<CompiledEffect> effect) {
  d_ = &device;
  Entry entry;
  entry.technique = std::move(technique);
  entry.effect = std::move(effect);
  VkEventCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_EVENT_CREATE_INFO;
  if (device.vkCreateEvent(device.device, &info, nullptr, &entry.done) != VK_SUCCESS) entry.done = VK_NULL_HANDLE;
  entries_.push_back(std::move(entry));
}

void RetiredTechniques::mark(VkCommandBuffer commands) {
  for (Entry& entry : entries_)
    if (entry.done && !entry.marked) {
      d_->vkCmdSetEvent(commands, entry.done, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
      entry.marked = true;
    }
}

void RetiredTechniques::release_finished() {
  std::vector<Entry> kept;
  for (Entry& entry : entries_) {
    if (entry.marked && d_->vkGetEventStatus(d_->device, entry.done) == VK_EVENT_SET) {
      spent_.push_back(entry.done);
      entry.technique.reset();
      entry.effect.reset();
    } else {
      kept.push_back(std::move(entry));
    }
  }
  entries_ = std::move(kept);
}

void RetiredTechniques::destroy_all() {
  for (Entry& entry : entries_) {
    entry.technique.reset();
    entry.effect.reset();
    if (entry.done) d_->vkDestroyEvent(d_->device, entry.done, nullptr);
  }
  entries_.clear();
  for (VkEvent event : spent_) d_->vkDestroyEvent(d_->device, event, nullptr);
  spent_.clear();
}

}  // namespace pfx::fx::vulkan
