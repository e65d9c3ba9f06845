// What the layer knows of the application's Vulkan objects: for each instance and device the
// next layer's functions, and for each swapchain its images. Looked up by the dispatch key the
// loader puts first in every dispatchable handle (a device's queues share the device's key).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include <pfx/vulkan_bridge.h>

#include "preset_watch.hpp"

namespace pfx::vulkan_layer {

struct Instance {
  VkInstance handle = VK_NULL_HANDLE;
  PFN_vkGetInstanceProcAddr next_get_proc = nullptr;
  PFN_vkDestroyInstance DestroyInstance = nullptr;
  PFN_vkEnumerateDeviceExtensionProperties EnumerateDeviceExtensionProperties = nullptr;
  // Whether the instance can describe external memory (Vulkan 1.1, or the 1.0 extensions added
  // at its creation): without it the device extensions the bridge needs may not be enabled.
  bool external_memory_capable = false;
};

struct Swapchain {
  VkSwapchainKHR handle = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
  std::vector<VkImage> images;
  std::vector<VkSemaphore> done;  // per image: the chain's result is in it
  bool opaque = false;            // composited opaque: its images' alpha means nothing
  bool usable = false;            // false: its presents pass through (the log said why)
};

struct Device {
  VkDevice handle = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkGetInstanceProcAddr next_instance_proc = nullptr;
  PFN_vkGetDeviceProcAddr next_get_proc = nullptr;
  PFN_vkSetDeviceLoaderData set_loader_data = nullptr;  // the loader's, for the bridge's command buffers
  PFN_vkDestroyDevice DestroyDevice = nullptr;
  PFN_vkGetDeviceQueue GetDeviceQueue = nullptr;
  PFN_vkGetDeviceQueue2 GetDeviceQueue2 = nullptr;
  PFN_vkCreateSwapchainKHR CreateSwapchainKHR = nullptr;
  PFN_vkDestroySwapchainKHR DestroySwapchainKHR = nullptr;
  PFN_vkGetSwapchainImagesKHR GetSwapchainImagesKHR = nullptr;
  PFN_vkQueuePresentKHR QueuePresentKHR = nullptr;
  PFN_vkCreateSemaphore CreateSemaphore = nullptr;
  PFN_vkDestroySemaphore DestroySemaphore = nullptr;
  PFN_vkDeviceWaitIdle DeviceWaitIdle = nullptr;
  bool bridge_extensions = false;  // the layer enabled what the shared-memory path needs
  bool failed = false;             // a chain failed: every present of the device passes through
  std::map<VkQueue, uint32_t> queue_families;
  std::map<VkQueue, pfx_vk_bridge*> bridges;  // one per presenting queue, made at its first present
  // The preset file, from the first bridge on: an edit applies to every bridge of the device.
  std::unique_ptr<inject::PresetWatch> preset_watch;
  std::map<VkSwapchainKHR, std::unique_ptr<Swapchain>> swapchains;
};

// The dispatch key of a dispatchable handle.
template <typename Handle>
void* key_of(Handle handle) {
  return *reinterpret_cast<void**>(handle);
}

// Every table, under one lock: the application may call from several threads. Presents hold it
// while the chain runs, which serialises the presents of different devices (rare) and keeps a
// device from being destroyed under a present.
struct LayerState {
  std::mutex mutex;
  std::map<void*, std::unique_ptr<Instance>> instances;
  std::map<void*, std::unique_ptr<Device>> devices;
};
LayerState& state();

// Looked up under state().mutex; null when the layer does not know the handle.
Instance* find_instance(void* key);
Device* find_device(void* key);

}  // namespace pfx::vulkan_layer
