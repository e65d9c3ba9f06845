#include "vk_functions.hpp"

namespace pfx::vk {
namespace {

template <typename Fn>
bool device_function(PFN_vkGetDeviceProcAddr get, VkDevice device, const char* name, Fn* out, std::string* error) {
  *out = reinterpret_cast<Fn>(get(device, name));
  if (*out) return true;
  *error = std::string("the Vulkan device does not give ") + name;
  return false;
}

}  // namespace

bool load_functions(VkInstance instance, VkDevice device, PFN_vkGetInstanceProcAddr get_instance_proc_addr,
                    PFN_vkGetDeviceProcAddr get_device_proc_addr, bool want_memory_fd, Functions* out,
                    std::string* error) {
  Functions f;
  f.GetPhysicalDeviceMemoryProperties = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties>(
      get_instance_proc_addr(instance, "vkGetPhysicalDeviceMemoryProperties"));
  // The extension's name first: an instance made for Vulkan 1.0 may call it only by that name (the
  // core one is there, but calling it breaks the rules); a newer one without the extension gets null.
  f.GetPhysicalDeviceProperties2 = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties2>(
      get_instance_proc_addr(instance, "vkGetPhysicalDeviceProperties2KHR"));
  if (!f.GetPhysicalDeviceProperties2)
    f.GetPhysicalDeviceProperties2 = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties2>(
        get_instance_proc_addr(instance, "vkGetPhysicalDeviceProperties2"));
  f.GetPhysicalDeviceFormatProperties = reinterpret_cast<PFN_vkGetPhysicalDeviceFormatProperties>(
      get_instance_proc_addr(instance, "vkGetPhysicalDeviceFormatProperties"));
  if (!f.GetPhysicalDeviceMemoryProperties || !f.GetPhysicalDeviceFormatProperties) {
    *error = "the Vulkan instance does not give vkGetPhysicalDeviceMemoryProperties or "
             "vkGetPhysicalDeviceFormatProperties";
    return false;
  }
  const PFN_vkGetDeviceProcAddr g = get_device_proc_addr;
  const bool ok = device_function(g, device, "vkCreateCommandPool", &f.CreateCommandPool, error) &&
                  device_function(g, device, "vkDestroyCommandPool", &f.DestroyCommandPool, error) &&
                  device_function(g, device, "vkAllocateCommandBuffers", &f.AllocateCommandBuffers, error) &&
                  device_function(g, device, "vkBeginCommandBuffer", &f.BeginCommandBuffer, error) &&
                  device_function(g, device, "vkEndCommandBuffer", &f.EndCommandBuffer, error) &&
                  device_function(g, device, "vkResetCommandBuffer", &f.ResetCommandBuffer, error) &&
                  device_function(g, device, "vkCmdPipelineBarrier", &f.CmdPipelineBarrier, error) &&
                  device_function(g, device, "vkCmdCopyImage", &f.CmdCopyImage, error) &&
                  device_function(g, device, "vkCmdBlitImage", &f.CmdBlitImage, error) &&
                  device_function(g, device, "vkCmdCopyImageToBuffer", &f.CmdCopyImageToBuffer, error) &&
                  device_function(g, device, "vkCmdCopyBufferToImage", &f.CmdCopyBufferToImage, error) &&
                  device_function(g, device, "vkQueueSubmit", &f.QueueSubmit, error) &&
                  device_function(g, device, "vkCreateFence", &f.CreateFence, error) &&
                  device_function(g, device, "vkDestroyFence", &f.DestroyFence, error) &&
                  device_function(g, device, "vkWaitForFences", &f.WaitForFences, error) &&
                  device_function(g, device, "vkGetFenceStatus", &f.GetFenceStatus, error) &&
                  device_function(g, device, "vkResetFences", &f.ResetFences, error) &&
                  device_function(g, device, "vkCreateImage", &f.CreateImage, error) &&
                  device_function(g, device, "vkDestroyImage", &f.DestroyImage, error) &&
                  device_function(g, device, "vkCreateBuffer", &f.CreateBuffer, error) &&
                  device_function(g, device, "vkDestroyBuffer", &f.DestroyBuffer, error) &&
                  device_function(g, device, "vkGetImageMemoryRequirements", &f.GetImageMemoryRequirements, error) &&
                  device_function(g, device, "vkGetBufferMemoryRequirements", &f.GetBufferMemoryRequirements, error) &&
                  device_function(g, device, "vkAllocateMemory", &f.AllocateMemory, error) &&
                  device_function(g, device, "vkFreeMemory", &f.FreeMemory, error) &&
                  device_function(g, device, "vkBindImageMemory", &f.BindImageMemory, error) &&
                  device_function(g, device, "vkBindBufferMemory", &f.BindBufferMemory, error) &&
                  device_function(g, device, "vkMapMemory", &f.MapMemory, error) &&
                  device_function(g, device, "vkUnmapMemory", &f.UnmapMemory, error);
  if (!ok) return false;
  // Only asked for when the caller says the device has the extension: a loader may hand out a
  // pointer for an extension the device was not created with.
  if (want_memory_fd)
    f.GetMemoryFdKHR = reinterpret_cast<PFN_vkGetMemoryFdKHR>(get_device_proc_addr(device, "vkGetMemoryFdKHR"));
  *out = f;
  return true;
}

std::string result_name(VkResult result) {
  switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_INVALID_EXTERNAL_HANDLE: return "VK_ERROR_INVALID_EXTERNAL_HANDLE";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    default: return "VkResult " + std::to_string(static_cast<int>(result));
  }
}

}  // namespace pfx::vk
