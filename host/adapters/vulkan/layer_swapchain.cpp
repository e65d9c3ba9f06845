// vkCreateSwapchainKHR and vkDestroySwapchainKHR as the layer sees them: transfer usage is added to
// the images (the bridge copies out of and back into them), and each image gets a semaphore the
// present waits on.
#include "layer_calls.hpp"
#include "layer_state.hpp"

namespace pfx::vulkan_layer {
namespace {

constexpr VkImageUsageFlags kTransfer = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

// Why the bridge cannot work on this swapchain's images, or "" when it can.
std::string unusable_because(const VkSwapchainCreateInfoKHR& info) {
  switch (info.imageFormat) {
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_A2R10G10B10_UNORM_PACK32: break;
    default:
      return "its format (VkFormat " + std::to_string(int(info.imageFormat)) + ") is not an 8-bit RGBA or 10-bit RGB one";
  }
  if (info.imageColorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
    return "its colour space (VkColorSpaceKHR " + std::to_string(int(info.imageColorSpace)) + ") is not sRGB";
  if (info.imageArrayLayers != 1) return "its images have several layers";
  return "";
}

// The images and a semaphore for each; false when they cannot be had.
bool keep_images(Device* d, Swapchain* s) {
  uint32_t count = 0;
  if (d->GetSwapchainImagesKHR(d->handle, s->handle, &count, nullptr) != VK_SUCCESS) return false;
  s->images.resize(count);
  if (d->GetSwapchainImagesKHR(d->handle, s->handle, &count, s->images.data()) != VK_SUCCESS) return false;
  s->images.resize(count);
  VkSemaphoreCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
  for (uint32_t i = 0; i < count; ++i) {
    VkSemaphore semaphore = VK_NULL_HANDLE;
    if (d->CreateSemaphore(d->handle, &info, nullptr, &semaphore) != VK_SUCCESS) return false;
    s->done.push_back(semaphore);
  }
  return true;
}

}  // namespace

VKAPI_ATTR VkResult VKAPI_CALL CreateSwapchainKHR(VkDevice device, const VkSwapchainCreateInfoKHR* info,
                                                  const VkAllocationCallbacks* allocator, VkSwapchainKHR* swapchain) {
  std::lock_guard<std::mutex> lock(state().mutex);
  Device* d = find_device(key_of(device));
  if (!d) return VK_ERROR_INITIALIZATION_FAILED;
  const std::string why_not = unusable_because(*info);
  VkSwapchainCreateInfoKHR ours = *info;
  if (why_not.empty()) ours.imageUsage |= kTransfer;
  VkResult result = d->CreateSwapchainKHR(device, &ours, allocator, swapchain);
  bool with_transfer = why_not.empty() && result == VK_SUCCESS;
  if (result != VK_SUCCESS && why_not.empty()) {
    with_transfer = false;  // the surface may not take transfer usage: as the application asked
    result = d->CreateSwapchainKHR(device, info, allocator, swapchain);
  }
  if (result != VK_SUCCESS) return result;
  auto record = std::make_unique<Swapchain>();
  record->handle = *swapchain;
  record->format = info->imageFormat;
  record->extent = info->imageExtent;
  record->opaque = info->compositeAlpha == VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!why_not.empty()) log_once("swapchain format", "the swapchain's frames pass through: " + why_not);
  else if (!with_transfer) log_once("swapchain usage", "the swapchain's frames pass through: its images cannot be copied");
  record->usable = with_transfer && keep_images(d, record.get());
  d->swapchains[*swapchain] = std::move(record);
  return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL DestroySwapchainKHR(VkDevice device, VkSwapchainKHR swapchain,
                                               const VkAllocationCallbacks* allocator) {
  std::lock_guard<std::mutex> lock(state().mutex);
  Device* d = find_device(key_of(device));
  if (!d) return;
  auto found = d->swapchains.find(swapchain);
  if (found != d->swapchains.end()) {
    // A present may still wait on the semaphores: the bridge's copies are done (each run waits for
    // the last one), but the presentation engine's wait is not known; the device is idled first,
    // as the application must have done before destroying what a present uses.
    if (!found->second->done.empty()) d->DeviceWaitIdle(device);
    for (VkSemaphore semaphore : found->second->done) d->DestroySemaphore(device, semaphore, nullptr);
    d->swapchains.erase(found);
  }
  d->DestroySwapchainKHR(device, swapchain, allocator);
}

}  // namespace pfx::vulkan_layer
