// One submission of the bridge's work for a caller's image: it waits on the image's semaphores
// and signals the image's own, as pfx_vk_image describes.
#pragma once

#include <string>

#include <pfx/vulkan_bridge.h>

#include "vk_functions.hpp"

namespace pfx::vk {

// Submits `commands` (none when null) to `queue` with `fence` (may be null). With `wait`, waits
// on the image's wait_semaphores, at its wait_stages or, where it gives none, at
// default_wait_stage; with `signal`, signals its signal_semaphore. False with *error.
bool submit_frame(const Functions& f, VkQueue queue, VkCommandBuffer commands, VkFence fence, const pfx_vk_image& image,
                  VkPipelineStageFlags default_wait_stage, bool wait, bool signal, std::string* error);

}  // namespace pfx::vk
