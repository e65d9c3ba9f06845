// vkCreateInstance and vkDestroyInstance as the layer sees them: the next layer's functions are
// kept, and a Vulkan 1.0 instance gets the two extensions that let a device share memory.
#include <cstring>
#include <vector>

#include "layer_calls.hpp"
#include "layer_state.hpp"

namespace pfx::vulkan_layer {
namespace {

VkLayerInstanceCreateInfo* link_info(const VkInstanceCreateInfo* info) {
  auto* item = static_cast<const VkBaseInStructure*>(info->pNext);
  for (; item; item = item->pNext) {
    auto* layer_info = reinterpret_cast<VkLayerInstanceCreateInfo*>(const_cast<VkBaseInStructure*>(item));
    if (item->sType == VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO && layer_info->function == VK_LAYER_LINK_INFO)
      return layer_info;
  }
  return nullptr;
}

bool names(const VkInstanceCreateInfo* info, const char* name) {
  for (uint32_t i = 0; i < info->enabledExtensionCount; ++i)
    if (std::strcmp(info->ppEnabledExtensionNames[i], name) == 0) return true;
  return false;
}

}  // namespace

VKAPI_ATTR VkResult VKAPI_CALL CreateInstance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* allocator,
                                              VkInstance* instance) {
  VkLayerInstanceCreateInfo* link = link_info(info);
  if (!link || !link->u.pLayerInfo) return VK_ERROR_INITIALIZATION_FAILED;
  const PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
  link->u.pLayerInfo = link->u.pLayerInfo->pNext;  // the next layer finds its own link
  VkLayerInstanceLink* const below = link->u.pLayerInfo;  // each layer below moves it on again
  auto create = reinterpret_cast<PFN_vkCreateInstance>(next(VK_NULL_HANDLE, "vkCreateInstance"));
  if (!create) return VK_ERROR_INITIALIZATION_FAILED;
  const uint32_t api = info->pApplicationInfo ? info->pApplicationInfo->apiVersion : VK_API_VERSION_1_0;
  bool capable = api >= VK_API_VERSION_1_1;
  std::vector<const char*> extensions(info->ppEnabledExtensionNames,
                                      info->ppEnabledExtensionNames + info->enabledExtensionCount);
  // A layer cannot ask what the instance offers before it exists (the functions for that are the
  // loader's, not the chain's): the extensions are asked for, and the instance made again without
  // them if that fails.
  if (!capable) {
    capable = true;
    for (const char* wanted : {"VK_KHR_get_physical_device_properties2", "VK_KHR_external_memory_capabilities"})
      if (!names(info, wanted)) extensions.push_back(wanted);
  }
  VkInstanceCreateInfo ours = *info;
  ours.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  ours.ppEnabledExtensionNames = extensions.data();
  VkResult result = create(&ours, allocator, instance);
  if (result != VK_SUCCESS && extensions.size() != info->enabledExtensionCount) {
    capable = api >= VK_API_VERSION_1_1;  // as the application asked, without ours
    link->u.pLayerInfo = below;
    result = create(info, allocator, instance);
  }
  if (result != VK_SUCCESS) return result;
  auto record = std::make_unique<Instance>();
  record->handle = *instance;
  record->next_get_proc = next;
  record->DestroyInstance = reinterpret_cast<PFN_vkDestroyInstance>(next(*instance, "vkDestroyInstance"));
  record->EnumerateDeviceExtensionProperties = reinterpret_cast<PFN_vkEnumerateDeviceExtensionProperties>(
      next(*instance, "vkEnumerateDeviceExtensionProperties"));
  record->external_memory_capable = capable;
  std::lock_guard<std::mutex> lock(state().mutex);
  state().instances[key_of(*instance)] = std::move(record);
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL DestroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator) {
  if (!instance) return;
  std::unique_ptr<Instance> record;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    auto found = state().instances.find(key_of(instance));
    if (found == state().instances.end()) return;
    record = std::move(found->second);
    state().instances.erase(found);
  }
  record->DestroyInstance(instance, allocator);
}

}  // namespace pfx::vulkan_layer
