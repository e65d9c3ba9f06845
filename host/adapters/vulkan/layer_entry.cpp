// The layer's two exported functions (named in its manifest): the loader and the layers above ask
// them for every Vulkan function, and get the layer's own for the calls it stands in for, the next
// layer's for the rest.
#include <cstring>

#include "layer_calls.hpp"
#include "layer_state.hpp"

namespace pfx::vulkan_layer {
namespace {

struct Named {
  const char* name;
  PFN_vkVoidFunction function;
};

#define PFX_LAYER_CALL(name) {"vk" #name, reinterpret_cast<PFN_vkVoidFunction>(&name)}
const Named kDeviceCalls[] = {PFX_LAYER_CALL(DestroyDevice),       PFX_LAYER_CALL(GetDeviceQueue),
                              PFX_LAYER_CALL(GetDeviceQueue2),     PFX_LAYER_CALL(CreateSwapchainKHR),
                              PFX_LAYER_CALL(DestroySwapchainKHR), PFX_LAYER_CALL(QueuePresentKHR)};
const Named kInstanceCalls[] = {PFX_LAYER_CALL(CreateInstance), PFX_LAYER_CALL(DestroyInstance),
                                PFX_LAYER_CALL(CreateDevice)};
#undef PFX_LAYER_CALL

template <size_t N>
PFN_vkVoidFunction own(const Named (&calls)[N], const char* name) {
  for (const auto& call : calls)
    if (std::strcmp(call.name, name) == 0) return call.function;
  return nullptr;
}

}  // namespace
}  // namespace pfx::vulkan_layer

using namespace pfx::vulkan_layer;

extern "C" __attribute__((visibility("default"))) VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL
pfx_layer_GetDeviceProcAddr(VkDevice device, const char* name);

extern "C" __attribute__((visibility("default"))) VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL
pfx_layer_GetInstanceProcAddr(VkInstance instance, const char* name) {
  if (std::strcmp(name, "vkGetInstanceProcAddr") == 0)
    return reinterpret_cast<PFN_vkVoidFunction>(&pfx_layer_GetInstanceProcAddr);
  if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
    return reinterpret_cast<PFN_vkVoidFunction>(&pfx_layer_GetDeviceProcAddr);
  if (PFN_vkVoidFunction function = own(kInstanceCalls, name)) return function;
  if (PFN_vkVoidFunction function = own(kDeviceCalls, name)) return function;
  if (!instance) return nullptr;
  PFN_vkGetInstanceProcAddr next = nullptr;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    if (const Instance* known = find_instance(key_of(instance))) next = known->next_get_proc;
  }
  return next ? next(instance, name) : nullptr;
}

extern "C" __attribute__((visibility("default"))) VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL
pfx_layer_GetDeviceProcAddr(VkDevice device, const char* name) {
  if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
    return reinterpret_cast<PFN_vkVoidFunction>(&pfx_layer_GetDeviceProcAddr);
  PFN_vkGetDeviceProcAddr next = nullptr;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    if (const Device* known = find_device(key_of(device))) next = known->next_get_proc;
  }
  if (!next) return nullptr;
  // The layer's own only where the device has the function at all (vkGetDeviceQueue2 on 1.0).
  if (PFN_vkVoidFunction function = own(kDeviceCalls, name)) return next(device, name) ? function : nullptr;
  return next(device, name);
}
