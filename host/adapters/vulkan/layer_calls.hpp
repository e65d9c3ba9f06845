// The Vulkan calls the layer stands in for (layer_entry.cpp hands them out by name), and what they
// share: the log and the bridge's settings.
#pragma once

#include <string>

#include <vulkan/vulkan.h>

#include <pfx/vulkan_bridge.h>

#include "inject_settings.hpp"

namespace pfx::vulkan_layer {

VKAPI_ATTR VkResult VKAPI_CALL CreateInstance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* allocator,
                                              VkInstance* instance);
VKAPI_ATTR void VKAPI_CALL DestroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator);
VKAPI_ATTR VkResult VKAPI_CALL CreateDevice(VkPhysicalDevice physical_device, const VkDeviceCreateInfo* info,
                                            const VkAllocationCallbacks* allocator, VkDevice* device);
VKAPI_ATTR void VKAPI_CALL DestroyDevice(VkDevice device, const VkAllocationCallbacks* allocator);
VKAPI_ATTR void VKAPI_CALL GetDeviceQueue(VkDevice device, uint32_t family, uint32_t index, VkQueue* queue);
VKAPI_ATTR void VKAPI_CALL GetDeviceQueue2(VkDevice device, const VkDeviceQueueInfo2* info, VkQueue* queue);
VKAPI_ATTR VkResult VKAPI_CALL CreateSwapchainKHR(VkDevice device, const VkSwapchainCreateInfoKHR* info,
                                                  const VkAllocationCallbacks* allocator, VkSwapchainKHR* swapchain);
VKAPI_ATTR void VKAPI_CALL DestroySwapchainKHR(VkDevice device, VkSwapchainKHR swapchain,
                                               const VkAllocationCallbacks* allocator);
VKAPI_ATTR VkResult VKAPI_CALL QueuePresentKHR(VkQueue queue, const VkPresentInfoKHR* info);

// One line to the log (stderr, or the file PFX_INJECT_LOG names); `once`: only the first time
// that key is seen.
void log_line(const std::string& message);
void log_once(const std::string& key, const std::string& message);

// The bridge's settings, read once from pfx-inject's variables (docs/inject.md). The strings stay
// valid for the life of the process.
struct BridgeSettings {
  const char* chain = nullptr;  // null: the default chain
  const char* set = nullptr;
  const char* preset = nullptr;
  const char* transfer = nullptr;
  const char* plugin_path = nullptr;
};
const BridgeSettings& bridge_settings();
// The same settings as pfx-inject's library reads them (captures, quit-after, the log file...).
const inject::InjectSettings& layer_inject_settings();

}  // namespace pfx::vulkan_layer
