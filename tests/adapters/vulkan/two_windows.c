/* An application with two windows that presents both swapchains in one vkQueuePresentKHR, for the
 * layer's tests: a case no program in Debian here makes (vkcube and mpv have one window). Each frame
 * it copies a picture into each window's image (a dark frame with a bright square: something bloom
 * changes), presents both, and after the last frame destroys its swapchains and its device at once,
 * without waiting for the presents to end, as some applications do on exit.
 *   two_windows FRAMES [minimise]
 * minimise: the second window is hidden from the screen (unmapped) at frame FRAMES/3 and shown again
 * at 2*FRAMES/3, both presented all along, as an X11 application does while minimised.
 * Plain C99, Xlib and Vulkan's WSI; exits 0 when every call succeeded. */
#define VK_USE_PLATFORM_XLIB_KHR
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#include "layout_barrier.h"

#define WINDOWS 2
#define MAX_IMAGES 8

typedef struct window_target {
  Window window;
  uint32_t width, height;
  VkSurfaceKHR surface;
  VkSwapchainKHR swapchain;
  VkImage images[MAX_IMAGES];
  uint32_t image_count;
  VkSemaphore acquired;
  VkBuffer picture;
  VkDeviceMemory picture_memory;
} window_target;

static int fail(const char* what) {
  fprintf(stderr, "two_windows: %s\n", what);
  return 0;
}

static int memory_type(VkPhysicalDevice gpu, uint32_t bits, VkMemoryPropertyFlags flags) {
  VkPhysicalDeviceMemoryProperties properties;
  uint32_t i;
  vkGetPhysicalDeviceMemoryProperties(gpu, &properties);
  for (i = 0; i < properties.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & flags) == flags) return (int)i;
  return -1;
}

/* The window's picture in a host buffer: dark grey, a white square in the middle (grey and white read
 * the same in RGBA and BGRA). */
static int make_picture(VkPhysicalDevice gpu, VkDevice device, window_target* t) {
  VkBufferCreateInfo info = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  VkMemoryAllocateInfo allocate = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  VkMemoryRequirements needs;
  unsigned char* bytes;
  uint32_t x, y;
  int type;
  info.size = (VkDeviceSize)t->width * t->height * 4;
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  if (vkCreateBuffer(device, &info, NULL, &t->picture) != VK_SUCCESS) return fail("no buffer");
  vkGetBufferMemoryRequirements(device, t->picture, &needs);
  type = memory_type(gpu, needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (type < 0) return fail("no host-visible memory");
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = (uint32_t)type;
  if (vkAllocateMemory(device, &allocate, NULL, &t->picture_memory) != VK_SUCCESS) return fail("out of memory");
  vkBindBufferMemory(device, t->picture, t->picture_memory, 0);
  if (vkMapMemory(device, t->picture_memory, 0, VK_WHOLE_SIZE, 0, (void**)&bytes) != VK_SUCCESS) return fail("no map");
  for (y = 0; y < t->height; ++y)
    for (x = 0; x < t->width; ++x) {
      const int inside = x * 3 >= t->width && x * 3 < t->width * 2 && y * 3 >= t->height && y * 3 < t->height * 2;
      unsigned char* texel = bytes + ((size_t)y * t->width + x) * 4;
      texel[0] = texel[1] = texel[2] = inside ? 255 : 40;
      texel[3] = 255;
    }
  vkUnmapMemory(device, t->picture_memory);
  return 1;
}

static int make_swapchain(VkPhysicalDevice gpu, VkDevice device, window_target* t) {
  VkSurfaceCapabilitiesKHR caps;
  VkSurfaceFormatKHR formats[32];
  uint32_t format_count = 32, i, chosen = 0;
  VkSwapchainCreateInfoKHR info = {VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  VkSemaphoreCreateInfo semaphore = {VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  if (vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, t->surface, &caps) != VK_SUCCESS) return fail("no capabilities");
  if (vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, t->surface, &format_count, formats) < 0 || !format_count)
    return fail("no surface formats");
  for (i = 0; i < format_count; ++i)
    if (formats[i].format == VK_FORMAT_B8G8R8A8_UNORM) chosen = i;
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) return fail("swapchain images take no copies");
  info.surface = t->surface;
  info.minImageCount = caps.minImageCount + 1;
  if (caps.maxImageCount && info.minImageCount > caps.maxImageCount) info.minImageCount = caps.maxImageCount;
  info.imageFormat = formats[chosen].format;
  info.imageColorSpace = formats[chosen].colorSpace;
  if (caps.currentExtent.width != 0xFFFFFFFFu) {
    t->width = caps.currentExtent.width;
    t->height = caps.currentExtent.height;
  }
  info.imageExtent.width = t->width;
  info.imageExtent.height = t->height;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (i = 0; i < 4; ++i)
    if (caps.supportedCompositeAlpha & (1u << i)) {
      info.compositeAlpha = (VkCompositeAlphaFlagBitsKHR)(1u << i);
      break;
    }
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
  info.clipped = VK_TRUE;
  if (vkCreateSwapchainKHR(device, &info, NULL, &t->swapchain) != VK_SUCCESS) return fail("no swapchain");
  t->image_count = MAX_IMAGES;
  if (vkGetSwapchainImagesKHR(device, t->swapchain, &t->image_count, t->images) < 0) return fail("no images");
  return vkCreateSemaphore(device, &semaphore, NULL, &t->acquired) == VK_SUCCESS || fail("no semaphore");
}

int main(int argc, char** argv) {
  const char* extensions[] = {VK_KHR_SURFACE_EXTENSION_NAME, VK_KHR_XLIB_SURFACE_EXTENSION_NAME};
  const char* device_extensions[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  const uint32_t sizes[WINDOWS][2] = {{160, 120}, {201, 97}};
  VkInstanceCreateInfo instance_info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  VkDeviceCreateInfo device_info = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  VkDeviceQueueCreateInfo queue_info = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  VkCommandPoolCreateInfo pool_info = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  VkCommandBufferAllocateInfo command_info = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  VkFenceCreateInfo fence_info = {VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkSemaphoreCreateInfo semaphore_info = {VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  window_target targets[WINDOWS];
  const float priority = 1.0f;
  Display* display;
  VkInstance instance;
  VkPhysicalDevice gpu;
  VkDevice device;
  VkQueue queue;
  VkCommandPool pool;
  VkCommandBuffer commands;
  VkFence done;
  VkSemaphore rendered;
  VkResult result;
  uint32_t count = 1, i;
  int frame, frames, minimise;
  if ((argc != 2 && argc != 3) || (frames = atoi(argv[1])) < 1) return fail("usage: two_windows FRAMES [minimise]"), 2;
  minimise = argc == 3 && strcmp(argv[2], "minimise") == 0;
  memset(targets, 0, sizeof targets);
  display = XOpenDisplay(NULL);
  if (!display) return fail("no X display"), 1;
  instance_info.enabledExtensionCount = 2;
  instance_info.ppEnabledExtensionNames = extensions;
  if (vkCreateInstance(&instance_info, NULL, &instance) != VK_SUCCESS) return fail("no instance"), 1;
  if (vkEnumeratePhysicalDevices(instance, &count, &gpu) < 0 || !count) return fail("no device"), 1;
  queue_info.queueFamilyIndex = 0;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = 1;
  device_info.ppEnabledExtensionNames = device_extensions;
  if (vkCreateDevice(gpu, &device_info, NULL, &device) != VK_SUCCESS) return fail("no logical device"), 1;
  vkGetDeviceQueue(device, 0, 0, &queue);
  for (i = 0; i < WINDOWS; ++i) {
    VkXlibSurfaceCreateInfoKHR surface_info = {VK_STRUCTURE_TYPE_XLIB_SURFACE_CREATE_INFO_KHR};
    VkBool32 presents = VK_FALSE;
    window_target* t = &targets[i];
    t->width = sizes[i][0];
    t->height = sizes[i][1];
    t->window = XCreateSimpleWindow(display, DefaultRootWindow(display), 0, 0, t->width, t->height, 0, 0, 0);
    XMapWindow(display, t->window);
    XFlush(display);
    surface_info.dpy = display;
    surface_info.window = t->window;
    if (vkCreateXlibSurfaceKHR(instance, &surface_info, NULL, &t->surface) != VK_SUCCESS) return fail("no surface"), 1;
    vkGetPhysicalDeviceSurfaceSupportKHR(gpu, 0, t->surface, &presents);
    if (!presents) return fail("queue family 0 cannot present to the window"), 1;
    if (!make_swapchain(gpu, device, t) || !make_picture(gpu, device, t)) return 1;
  }
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  if (vkCreateCommandPool(device, &pool_info, NULL, &pool) != VK_SUCCESS) return fail("no pool"), 1;
  command_info.commandPool = pool;
  command_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  command_info.commandBufferCount = 1;
  if (vkAllocateCommandBuffers(device, &command_info, &commands) != VK_SUCCESS) return fail("no command buffer"), 1;
  fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  if (vkCreateFence(device, &fence_info, NULL, &done) != VK_SUCCESS) return fail("no fence"), 1;
  if (vkCreateSemaphore(device, &semaphore_info, NULL, &rendered) != VK_SUCCESS) return fail("no semaphore"), 1;

  for (frame = 0; frame < frames; ++frame) {
    VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
    VkPresentInfoKHR present = {VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    VkPipelineStageFlags stages[WINDOWS];
    VkSemaphore waits[WINDOWS];
    VkSwapchainKHR swapchains[WINDOWS];
    uint32_t indices[WINDOWS];
    VkResult results[WINDOWS];
    if (minimise && (frame == frames / 3 || frame == 2 * frames / 3)) {
      /* Hidden from the screen and back, as a minimised window is (without a window manager to
       * iconify it, unmapped: what iconifying does to the window). */
      if (frame == frames / 3) XUnmapWindow(display, targets[1].window);
      else XMapWindow(display, targets[1].window);
      XSync(display, False);
      printf("two_windows: frame %d: second window %s\n", frame, frame == frames / 3 ? "hidden" : "shown again");
    }
    /* The last frame's submission is done, and with it the waits on the semaphores used again. */
    vkWaitForFences(device, 1, &done, VK_TRUE, UINT64_MAX);
    vkResetFences(device, 1, &done);
    for (i = 0; i < WINDOWS; ++i) {
      if (vkAcquireNextImageKHR(device, targets[i].swapchain, UINT64_MAX, targets[i].acquired, VK_NULL_HANDLE,
                                &indices[i]) < 0)
        return fail("could not acquire an image"), 1;
      waits[i] = targets[i].acquired;
      stages[i] = VK_PIPELINE_STAGE_TRANSFER_BIT;
      swapchains[i] = targets[i].swapchain;
    }
    vkResetCommandBuffer(commands, 0);
    vkBeginCommandBuffer(commands, &begin);
    for (i = 0; i < WINDOWS; ++i) {
      VkBufferImageCopy region;
      VkImage image = targets[i].images[indices[i]];
      memset(&region, 0, sizeof region);
      region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
      region.imageSubresource.layerCount = 1;
      region.imageExtent.width = targets[i].width;
      region.imageExtent.height = targets[i].height;
      region.imageExtent.depth = 1;
      layout_barrier(commands, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
      vkCmdCopyBufferToImage(commands, targets[i].picture, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      layout_barrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    }
    vkEndCommandBuffer(commands);
    submit.waitSemaphoreCount = WINDOWS;
    submit.pWaitSemaphores = waits;
    submit.pWaitDstStageMask = stages;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &rendered;
    if (vkQueueSubmit(queue, 1, &submit, done) != VK_SUCCESS) return fail("submit failed"), 1;
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &rendered;
    present.swapchainCount = WINDOWS;
    present.pSwapchains = swapchains;
    present.pImageIndices = indices;
    present.pResults = results;
    result = vkQueuePresentKHR(queue, &present);
    for (i = 0; i < WINDOWS; ++i)
      if (results[i] != VK_SUCCESS) printf("two_windows: frame %d: window %u presented with VkResult %d\n", frame, i + 1, results[i]);
    if (result < 0) return fail("present failed"), 1;
    for (i = 0; i < WINDOWS; ++i)
      if (results[i] < 0) return fail("a swapchain's present failed"), 1;
  }
  /* Gone at once, presents and all: no vkDeviceWaitIdle. */
  for (i = 0; i < WINDOWS; ++i) vkDestroySwapchainKHR(device, targets[i].swapchain, NULL);
  vkDestroyDevice(device, NULL);
  printf("two_windows: %d frames presented to two windows\n", frames);
  return 0;
}
