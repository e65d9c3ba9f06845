// vkCreateDevice and vkDestroyDevice as the layer sees them: the next layer's functions are kept,
// the extensions the bridge's shared-memory path needs are added where the device offers them,
// and the queues are noted with their families (a present names only the queue).
#include <cstring>
#include <vector>

#include "layer_calls.hpp"
#include "layer_state.hpp"

namespace pfx::vulkan_layer {
namespace {

// The loader's structure of the given kind: the link to the next layer, or its callbacks.
VkLayerDeviceCreateInfo* loader_info(const VkDeviceCreateInfo* info, VkLayerFunction function) {
  auto* item = static_cast<const VkBaseInStructure*>(info->pNext);
  for (; item; item = item->pNext) {
    auto* layer_info = reinterpret_cast<VkLayerDeviceCreateInfo*>(const_cast<VkBaseInStructure*>(item));
    if (item->sType == VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO && layer_info->function == function)
      return layer_info;
  }
  return nullptr;
}

// The application's extensions plus those of the bridge the device offers; *all: every one of
// the bridge's is there.
std::vector<const char*> with_bridge_extensions(const Instance& instance, VkPhysicalDevice physical_device,
                                                const VkDeviceCreateInfo* info, bool* all) {
  std::vector<const char*> names(info->ppEnabledExtensionNames,
                                 info->ppEnabledExtensionNames + info->enabledExtensionCount);
  uint32_t count = 0;
  std::vector<VkExtensionProperties> offered;
  if (instance.EnumerateDeviceExtensionProperties(physical_device, nullptr, &count, nullptr) == VK_SUCCESS) {
    offered.resize(count);
    if (instance.EnumerateDeviceExtensionProperties(physical_device, nullptr, &count, offered.data()) < 0) count = 0;
    offered.resize(count);
  }
  uint32_t wanted_count = 0;
  const char* const* wanted = pfx_vk_bridge_device_extensions(&wanted_count);
  *all = instance.external_memory_capable;
  for (uint32_t i = 0; i < wanted_count && *all; ++i) {
    bool present = false, on = false;
    for (const auto& extension : offered) present |= std::strcmp(extension.extensionName, wanted[i]) == 0;
    for (const char* name : names) on |= std::strcmp(name, wanted[i]) == 0;
    if (!present) *all = false;
    else if (!on) names.push_back(wanted[i]);
  }
  if (!*all) names.resize(info->enabledExtensionCount);
  return names;
}

template <typename Fn>
void next_device(const Device& device, const char* name, Fn* out) {
  *out = reinterpret_cast<Fn>(device.next_get_proc(device.handle, name));
}

void keep_functions(Device* d) {
  next_device(*d, "vkDestroyDevice", &d->DestroyDevice);
  next_device(*d, "vkGetDeviceQueue", &d->GetDeviceQueue);
  next_device(*d, "vkGetDeviceQueue2", &d->GetDeviceQueue2);
  next_device(*d, "vkCreateSwapchainKHR", &d->CreateSwapchainKHR);
  next_device(*d, "vkDestroySwapchainKHR", &d->DestroySwapchainKHR);
  next_device(*d, "vkGetSwapchainImagesKHR", &d->GetSwapchainImagesKHR);
  next_device(*d, "vkQueuePresentKHR", &d->QueuePresentKHR);
  next_device(*d, "vkCreateSemaphore", &d->CreateSemaphore);
  next_device(*d, "vkDestroySemaphore", &d->DestroySemaphore);
  next_device(*d, "vkDeviceWaitIdle", &d->DeviceWaitIdle);
}

}  // namespace

VKAPI_ATTR VkResult VKAPI_CALL CreateDevice(VkPhysicalDevice physical_device, const VkDeviceCreateInfo* info,
                                            const VkAllocationCallbacks* allocator, VkDevice* device) {
  VkLayerDeviceCreateInfo* link = loader_info(info, VK_LAYER_LINK_INFO);
  const VkLayerDeviceCreateInfo* callbacks = loader_info(info, VK_LOADER_DATA_CALLBACK);
  if (!link || !link->u.pLayerInfo) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr next_instance = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  const PFN_vkGetDeviceProcAddr next_device_proc = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;
  VkLayerDeviceLink* const below = link->u.pLayerInfo;  // each layer below moves it on again
  Instance instance;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    const Instance* known = find_instance(key_of(physical_device));
    if (!known) return VK_ERROR_INITIALIZATION_FAILED;
    instance = *known;
  }
  auto create = reinterpret_cast<PFN_vkCreateDevice>(next_instance(instance.handle, "vkCreateDevice"));
  if (!create) return VK_ERROR_INITIALIZATION_FAILED;
  bool bridge_extensions = false;
  std::vector<const char*> names = with_bridge_extensions(instance, physical_device, info, &bridge_extensions);
  VkDeviceCreateInfo ours = *info;
  ours.enabledExtensionCount = static_cast<uint32_t>(names.size());
  ours.ppEnabledExtensionNames = names.data();
  VkResult result = create(physical_device, &ours, allocator, device);
  if (result != VK_SUCCESS && names.size() != info->enabledExtensionCount) {
    bridge_extensions = false;  // as the application asked, without ours
    link->u.pLayerInfo = below;
    result = create(physical_device, info, allocator, device);
  }
  if (result != VK_SUCCESS) return result;
  auto record = std::make_unique<Device>();
  record->handle = *device;
  record->physical_device = physical_device;
  record->instance = instance.handle;
  record->next_instance_proc = next_instance;
  record->next_get_proc = next_device_proc;
  record->bridge_extensions = bridge_extensions;
  record->set_loader_data = callbacks ? callbacks->u.pfnSetDeviceLoaderData : nullptr;
  keep_functions(record.get());
  std::lock_guard<std::mutex> lock(state().mutex);
  state().devices[key_of(*device)] = std::move(record);
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL DestroyDevice(VkDevice device, const VkAllocationCallbacks* allocator) {
  if (!device) return;
  std::unique_ptr<Device> record;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    auto found = state().devices.find(key_of(device));
    if (found == state().devices.end()) return;
    record = std::move(found->second);
    state().devices.erase(found);
  }
  // The application may destroy its device with presents in flight: the bridges wait for their
  // own copies; the rest is the application's to have waited for, as Vulkan asks.
  for (auto& [queue, bridge] : record->bridges) pfx_vk_bridge_destroy(bridge);
  for (auto& [handle, swapchain] : record->swapchains)
    for (VkSemaphore semaphore : swapchain->done) record->DestroySemaphore(device, semaphore, nullptr);
  record->DestroyDevice(device, allocator);
}

VKAPI_ATTR void VKAPI_CALL GetDeviceQueue(VkDevice device, uint32_t family, uint32_t index, VkQueue* queue) {
  std::lock_guard<std::mutex> lock(state().mutex);
  Device* d = find_device(key_of(device));
  if (!d) return;
  d->GetDeviceQueue(device, family, index, queue);
  if (*queue) d->queue_families[*queue] = family;
}

VKAPI_ATTR void VKAPI_CALL GetDeviceQueue2(VkDevice device, const VkDeviceQueueInfo2* info, VkQueue* queue) {
  std::lock_guard<std::mutex> lock(state().mutex);
  Device* d = find_device(key_of(device));
  if (!d || !d->GetDeviceQueue2) return;
  d->GetDeviceQueue2(device, info, queue);
  if (*queue) d->queue_families[*queue] = info->queueFamilyIndex;
}

}  // namespace pfx::vulkan_layer
