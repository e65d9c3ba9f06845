// The bridge's command buffers and their submission for a caller's image: a submission waits on
// the image's semaphores and signals the image's own, as pfx_vk_image describes.
#pragma once

#include <string>

#include <pfx/vulkan_bridge.h>

#include "vk_functions.hpp"

namespace pfx::vk {

// A command pool whose buffers are reset one by one, and `count` primary buffers from it, each
// handed to set_loader_data when that is not null (a layer's loader callback: a command buffer
// made below the loader gets its dispatch table only from it). False with *error.
using SetLoaderData = VkResult(VKAPI_PTR*)(VkDevice, void*);
bool make_command_buffers(const Functions& f, VkDevice device, uint32_t queue_family_index,
                          SetLoaderData set_loader_data, uint32_t count, VkCommandPool* pool, VkCommandBuffer* buffers,
                          std::string* error);

// Submits `commands` (none when null) to `queue` with `fence` (may be null). With `wait`, waits
// on the image's wait_semaphores, at its wait_stages or, where it gives none, at
// default_wait_stage; with `signal`, signals its signal_semaphore. False with *error.
bool submit_frame(const Functions& f, VkQueue queue, VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image,
                  VkPipelineStageFlags default_wait_stage, bool wait, bool signal, std::string* error);

}  // namespace pfx::vk
