/* A Vulkan program in plain C, written from pfx/vulkan_bridge.h and docs/sdk.md alone, as an engine
 * would use the bridge: it puts a PNG into a VkImage of its own, runs a pfx chain over the image
 * through the bridge, reads the image back and compares it with a PNG pfx-render made from the same
 * input (within one code value).
 *
 *   bridge_c_test IN.png EXPECTED.png PLUGIN_DIR CHAIN rgba|bgra|a2b10g10r10|a2r10g10b10 shared|host|native|record [SET]
 *
 * SET: "effect.param=value" for the bridge's `set`, as pfx-render's --set took it.
 * "shared" lets the bridge share memory (and fails if it did not, or if it did not go by blits for
 * an 8-bit image and by copies for a 10-bit one); "host" forces host memory; both time the passes,
 * which keeps any chain on the GL path. "native" and "record" ask for nothing more, and fail unless
 * the chain runs natively (an all-FX chain): "native" through pfx_vk_bridge_run, "record" through
 * pfx_vk_bridge_record into a command buffer of this program's, which it submits itself.
 * Exit status 0 when every pixel's R, G and B are within one code of EXPECTED. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pfx/vulkan_bridge.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "layout_barrier.h"

typedef struct context {
  VkInstance instance;
  VkPhysicalDevice physical_device;
  VkDevice device;
  VkQueue queue;
  uint32_t family;
  int has_bridge_extensions;
  VkCommandPool pool;
} context;

typedef struct gpu_image {
  VkImage image;
  VkDeviceMemory image_memory;
  VkBuffer buffer; /* host-visible, tightly packed rows: the upload and the read-back */
  VkDeviceMemory buffer_memory;
  void* mapped;
  uint32_t width, height;
} gpu_image;

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
/* Under LeakSanitizer (./run test's second pass): the Vulkan loader unloads lavapipe at
 * vkDestroyInstance, and a block lavapipe keeps in its globals for the life of the process then
 * points nowhere and is reported as a leak of whatever is mapped there now (128 bytes, seen as
 * libpfxvulkan's or "<unknown module>"; with lavapipe kept loaded there is none). Keeping the
 * driver mapped lets LeakSanitizer see the block held, as it is. */
static void keep_driver_mapped(void) { (void)dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE); }
#else
static void keep_driver_mapped(void) {}
#endif

static int fail(const char* what) {
  fprintf(stderr, "bridge_c_test: %s\n", what);
  return 0;
}

static VkPhysicalDevice pick_device(VkInstance instance) {
  VkPhysicalDevice devices[16];
  uint32_t count = 16, i;
  VkPhysicalDevice chosen = VK_NULL_HANDLE;
  if (vkEnumeratePhysicalDevices(instance, &count, devices) < 0 || count == 0) return VK_NULL_HANDLE;
  chosen = devices[0];
  for (i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(devices[i], &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) chosen = devices[i];
  }
  return chosen;
}

/* Whether the device offers every extension the bridge's shared-memory path needs. */
static int offers_extensions(VkPhysicalDevice device, const char* const* wanted, uint32_t wanted_count) {
  VkExtensionProperties offered[512];
  uint32_t count = 512, i, j;
  vkEnumerateDeviceExtensionProperties(device, NULL, &count, offered);
  for (i = 0; i < wanted_count; ++i) {
    int found = 0;
    for (j = 0; j < count; ++j) found |= strcmp(offered[j].extensionName, wanted[i]) == 0;
    if (!found) return 0;
  }
  return 1;
}

static int make_context(context* c) {
  VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
  VkInstanceCreateInfo instance_info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  VkQueueFamilyProperties families[16];
  uint32_t family_count = 16, extension_count = 0;
  const char* const* extensions = pfx_vk_bridge_device_extensions(&extension_count);
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  VkDeviceCreateInfo device_info = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  VkCommandPoolCreateInfo pool_info = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  app.apiVersion = VK_API_VERSION_1_1;
  instance_info.pApplicationInfo = &app;
  if (vkCreateInstance(&instance_info, NULL, &c->instance) != VK_SUCCESS) return fail("no Vulkan instance");
  c->physical_device = pick_device(c->instance);
  if (!c->physical_device) return fail("no Vulkan device");
  vkGetPhysicalDeviceQueueFamilyProperties(c->physical_device, &family_count, families);
  for (c->family = 0; c->family < family_count; ++c->family)
    if (families[c->family].queueFlags & VK_QUEUE_GRAPHICS_BIT) break;
  if (c->family == family_count) return fail("no graphics queue");
  queue_info.queueFamilyIndex = c->family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  c->has_bridge_extensions = offers_extensions(c->physical_device, extensions, extension_count);
  if (c->has_bridge_extensions) {
    device_info.enabledExtensionCount = extension_count;
    device_info.ppEnabledExtensionNames = extensions;
  }
  if (vkCreateDevice(c->physical_device, &device_info, NULL, &c->device) != VK_SUCCESS) return fail("no device");
  vkGetDeviceQueue(c->device, c->family, 0, &c->queue);
  pool_info.queueFamilyIndex = c->family;
  return vkCreateCommandPool(c->device, &pool_info, NULL, &c->pool) == VK_SUCCESS || fail("no command pool");
}

static int memory_type(const context* c, uint32_t bits, VkMemoryPropertyFlags flags) {
  VkPhysicalDeviceMemoryProperties properties;
  uint32_t i;
  vkGetPhysicalDeviceMemoryProperties(c->physical_device, &properties);
  for (i = 0; i < properties.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & flags) == flags) return (int)i;
  return -1;
}

static int allocate(const context* c, VkMemoryRequirements needs, VkMemoryPropertyFlags flags, VkDeviceMemory* out) {
  VkMemoryAllocateInfo info = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  const int type = memory_type(c, needs.memoryTypeBits, flags);
  if (type < 0) return fail("no memory type");
  info.allocationSize = needs.size;
  info.memoryTypeIndex = (uint32_t)type;
  return vkAllocateMemory(c->device, &info, NULL, out) == VK_SUCCESS || fail("out of memory");
}

static int make_image(const context* c, VkFormat format, uint32_t width, uint32_t height, gpu_image* g) {
  VkImageCreateInfo info = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  VkBufferCreateInfo buffer_info = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  VkMemoryRequirements needs;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent.width = width;
  info.extent.height = height;
  info.extent.depth = 1;
  info.mipLevels = info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT; /* what the bridge asks */
  g->width = width;
  g->height = height;
  if (vkCreateImage(c->device, &info, NULL, &g->image) != VK_SUCCESS) return fail("no image");
  vkGetImageMemoryRequirements(c->device, g->image, &needs);
  if (!allocate(c, needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &g->image_memory)) return 0;
  vkBindImageMemory(c->device, g->image, g->image_memory, 0);
  buffer_info.size = (VkDeviceSize)width * height * 4;
  buffer_info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (vkCreateBuffer(c->device, &buffer_info, NULL, &g->buffer) != VK_SUCCESS) return fail("no buffer");
  vkGetBufferMemoryRequirements(c->device, g->buffer, &needs);
  if (!allocate(c, needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                &g->buffer_memory))
    return 0;
  vkBindBufferMemory(c->device, g->buffer, g->buffer_memory, 0);
  return vkMapMemory(c->device, g->buffer_memory, 0, VK_WHOLE_SIZE, 0, &g->mapped) == VK_SUCCESS || fail("no map");
}

/* upload: buffer -> image, leaving it GENERAL (a layout an engine might hand over); else image -> buffer. */
static int transfer(const context* c, const gpu_image* g, int upload) {
  VkCommandBufferAllocateInfo info = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
  VkBufferImageCopy region;
  VkCommandBuffer commands;
  memset(&region, 0, sizeof region);
  region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  region.imageSubresource.layerCount = 1;
  region.imageExtent.width = g->width;
  region.imageExtent.height = g->height;
  region.imageExtent.depth = 1;
  info.commandPool = c->pool;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  if (vkAllocateCommandBuffers(c->device, &info, &commands) != VK_SUCCESS) return fail("no command buffer");
  vkBeginCommandBuffer(commands, &begin);
  if (upload) {
    layout_barrier(commands, g->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(commands, g->buffer, g->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    layout_barrier(commands, g->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
  } else {
    vkCmdCopyImageToBuffer(commands, g->image, VK_IMAGE_LAYOUT_GENERAL, g->buffer, 1, &region);
  }
  vkEndCommandBuffer(commands);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  if (vkQueueSubmit(c->queue, 1, &submit, VK_NULL_HANDLE) != VK_SUCCESS) return fail("submit failed");
  vkQueueWaitIdle(c->queue);
  vkFreeCommandBuffers(c->device, c->pool, 1, &commands);
  return 1;
}

/* How the bridge said it moves frames of the image's size through shared memory: 'b' blits, 'c'
 * copies, 0 not said (docs/sdk.md: an 8-bit image goes by blits where the device can blit it,
 * which lavapipe can). */
static char said_way = 0;

static void log_line(void* user, int level, const char* message) {
  (void)user;
  fprintf(stderr, "bridge (%d): %s\n", level, message);
  if (strstr(message, " frames: Vulkan blits them")) said_way = 'b';
  if (strstr(message, " frames: copied as they are")) said_way = 'c';
}

/* What the bridge says of the run: the chain, whether a pass ran, the passes' times (glFinish and a
 * clock on a software renderer: complete at once; GPU timestamps arrive later) and the unit. The
 * native path times nothing and has no GL to time the unit on. */
static int report_run(pfx_vk_bridge* bridge, const char* chain, uint32_t width, uint32_t height, int native) {
  pfx_vk_frame_times times;
  const int runs_effects = strcmp(chain, "none") != 0;
  double copy_ms;
  uint32_t i;
  if (native) {
    printf("chain: %s; passes ran: %d\n", pfx_vk_bridge_chain(bridge), pfx_vk_bridge_ran_passes(bridge));
    if (strcmp(pfx_vk_bridge_chain(bridge), chain) != 0) return fail("the bridge names another chain");
    if (pfx_vk_bridge_ran_passes(bridge) != runs_effects) return fail("the bridge says otherwise of the passes it ran");
    return pfx_vk_bridge_copy_pass_ms(bridge, width, height) == 0 || fail("a copy pass timed with no GL");
  }
  memset(&times, 0, sizeof times);
  times.struct_size = sizeof times;
  if (pfx_vk_bridge_frame_times(bridge, &times) != PFX_VK_OK) return fail("pfx_vk_bridge_frame_times failed");
  printf("chain: %s; passes ran: %d; timing: %s, frame %lu, %u passes, %.3f ms\n", pfx_vk_bridge_chain(bridge),
         pfx_vk_bridge_ran_passes(bridge), times.timing, (unsigned long)times.frame, times.pass_count, times.total_ms);
  for (i = 0; i < times.pass_count; ++i) printf("  %s.%s %.3f ms\n", times.passes[i].effect, times.passes[i].pass, times.passes[i].ms);
  if (strcmp(pfx_vk_bridge_chain(bridge), chain) != 0) return fail("the bridge names another chain");
  if (pfx_vk_bridge_ran_passes(bridge) != runs_effects) return fail("the bridge says otherwise of the passes it ran");
  if (runs_effects && strcmp(times.timing, "finish+clock") == 0 && (times.frame != 1 || times.pass_count == 0))
    return fail("no pass times for the frame that ran");
  copy_ms = pfx_vk_bridge_copy_pass_ms(bridge, width, height);
  printf("copy pass: %.3f ms\n", copy_ms);
  return copy_ms > 0 || fail("no copy pass time");
}

/* Whether the bridge submits, for a chain that runs (always) or none: an empty batch that passes the
 * semaphores on, unless the image says PFX_VK_IMAGE_MAY_SKIP, and then nothing. A caller built
 * against the first pfx_vk_image, which ended at result_pixels, still runs, its flags unread. */
static int check_submissions(pfx_vk_bridge* bridge, pfx_vk_image* image, const char* chain) {
  const int runs_effects = strcmp(chain, "none") != 0;
  printf("submitted: %d\n", pfx_vk_bridge_submitted(bridge));
  if (!pfx_vk_bridge_submitted(bridge)) return fail("a run without PFX_VK_IMAGE_MAY_SKIP submitted nothing");
  if (runs_effects) return 1; /* another run would change the picture again */
  image->flags = PFX_VK_IMAGE_MAY_SKIP;
  if (pfx_vk_bridge_run(bridge, image) != PFX_VK_OK) return fail(pfx_vk_bridge_last_error(bridge));
  printf("submitted with PFX_VK_IMAGE_MAY_SKIP: %d\n", pfx_vk_bridge_submitted(bridge));
  if (pfx_vk_bridge_submitted(bridge)) return fail("a frame left alone under PFX_VK_IMAGE_MAY_SKIP was submitted");
  image->struct_size = (uint32_t)(offsetof(pfx_vk_image, result_pixels) + sizeof image->result_pixels);
  if (pfx_vk_bridge_run(bridge, image) != PFX_VK_OK) return fail(pfx_vk_bridge_last_error(bridge));
  if (!pfx_vk_bridge_submitted(bridge)) return fail("a first-version image's flags were read");
  return 1;
}

/* The chain recorded into a command buffer of this program's, submitted and waited for here. */
static pfx_vk_status record_chain(const context* c, pfx_vk_bridge* bridge, const pfx_vk_image* image) {
  VkCommandBufferAllocateInfo info = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
  VkCommandBuffer commands;
  pfx_vk_status status;
  info.commandPool = c->pool;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  if (vkAllocateCommandBuffers(c->device, &info, &commands) != VK_SUCCESS) return PFX_VK_VULKAN_FAILED;
  vkBeginCommandBuffer(commands, &begin);
  status = pfx_vk_bridge_record(bridge, commands, image);
  vkEndCommandBuffer(commands);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  if (status == PFX_VK_OK && vkQueueSubmit(c->queue, 1, &submit, VK_NULL_HANDLE) != VK_SUCCESS)
    status = PFX_VK_VULKAN_FAILED;
  vkQueueWaitIdle(c->queue);
  vkFreeCommandBuffers(c->device, c->pool, 1, &commands);
  return status;
}

static int run_bridge(const context* c, const gpu_image* g, VkFormat format, const char* plugins, const char* chain,
                      const char* set, const char* path) {
  pfx_vk_bridge_desc desc;
  pfx_vk_image image;
  pfx_vk_bridge* bridge = NULL;
  char error[512];
  pfx_vk_status status;
  const int host_memory = strcmp(path, "host") == 0, records = strcmp(path, "record") == 0;
  const int native = records || strcmp(path, "native") == 0;
  const char* want_path = native ? "native" : host_memory ? "host memory" : "shared memory";
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.instance = c->instance;
  desc.physical_device = c->physical_device;
  desc.device = c->device;
  desc.get_instance_proc_addr = vkGetInstanceProcAddr;
  desc.get_device_proc_addr = vkGetDeviceProcAddr;
  desc.queue = c->queue;
  desc.queue_family_index = c->family;
  desc.device_has_bridge_extensions = c->has_bridge_extensions;
  desc.chain = chain;
  desc.set = set;
  desc.plugin_path = plugins;
  desc.flags = native ? 0u : (host_memory ? PFX_VK_FORCE_HOST_MEMORY : 0) | PFX_VK_TIME_PASSES;
  desc.log = log_line;
  if (pfx_vk_bridge_create(&desc, &bridge, error, sizeof error) != PFX_VK_OK) return fail(error);
  memset(&image, 0, sizeof image);
  image.struct_size = sizeof image;
  image.image = g->image;
  image.format = format;
  image.width = g->width;
  image.height = g->height;
  image.layout = VK_IMAGE_LAYOUT_GENERAL;
  status = records ? record_chain(c, bridge, &image) : pfx_vk_bridge_run(bridge, &image);
  if (status != PFX_VK_OK) fprintf(stderr, "bridge_c_test: run: %s\n", pfx_vk_bridge_last_error(bridge));
  printf("path: %s\n", pfx_vk_bridge_path(bridge));
  if (strcmp(pfx_vk_bridge_path(bridge), want_path) != 0) status = PFX_VK_BAD_ARGUMENT;
  if (status == PFX_VK_OK && !report_run(bridge, chain, image.width, image.height, native)) status = PFX_VK_BAD_ARGUMENT;
  if (status == PFX_VK_OK && !records && !check_submissions(bridge, &image, chain)) status = PFX_VK_BAD_ARGUMENT;
  if (status == PFX_VK_OK && !host_memory && !native && strcmp(chain, "none") != 0) {
    const int eight_bit = format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_B8G8R8A8_UNORM;
    printf("shared memory by %s\n", said_way == 'b' ? "blits" : said_way == 'c' ? "copies" : "(not said)");
    if (said_way != (eight_bit ? 'b' : 'c')) status = PFX_VK_BAD_ARGUMENT;
  }
  vkQueueWaitIdle(c->queue);
  pfx_vk_bridge_destroy(bridge);
  return status == PFX_VK_OK || fail("the bridge did not run as asked");
}

/* The largest difference of R, G or B; *changed counts pixels that differ from `input`. */
static int compare(const unsigned char* got, const unsigned char* want, const unsigned char* input, size_t pixels,
                   int bgra, size_t* changed) {
  size_t i;
  int c, worst = 0;
  *changed = 0;
  for (i = 0; i < pixels; ++i) {
    int differs = 0;
    for (c = 0; c < 3; ++c) {
      const int g = got[i * 4 + (size_t)(bgra ? 2 - c : c)];
      const int d = abs(g - (int)want[i * 4 + (size_t)c]);
      if (d > worst) worst = d;
      differs |= g != input[i * 4 + (size_t)c];
    }
    *changed += (size_t)differs;
  }
  return worst;
}

/* 8-bit codes to 10-bit ones and back, each to the nearest. */
static uint32_t ten_from_eight(unsigned char v) { return ((uint32_t)v * 1023u + 127u) / 255u; }
static unsigned char eight_from_ten(uint32_t v) { return (unsigned char)((v * 255u + 511u) / 1023u); }

/* A2B10G10R10: red in the lowest 10 bits, then green, blue and a 2-bit alpha; A2R10G10B10 (bgr):
 * blue in the lowest bits and red above green. */
static void pack_ten_bit(const unsigned char* rgba, size_t pixels, int bgr, void* out) {
  size_t i;
  for (i = 0; i < pixels; ++i) {
    const uint32_t alpha = ((uint32_t)rgba[i * 4 + 3] * 3u + 127u) / 255u;
    const uint32_t word = ten_from_eight(rgba[i * 4 + (bgr ? 2 : 0)]) | ten_from_eight(rgba[i * 4 + 1]) << 10 |
                          ten_from_eight(rgba[i * 4 + (bgr ? 0 : 2)]) << 20 | alpha << 30;
    memcpy((unsigned char*)out + i * 4, &word, 4);
  }
}

static void unpack_ten_bit(const void* in, size_t pixels, int bgr, unsigned char* rgba) {
  size_t i;
  for (i = 0; i < pixels; ++i) {
    uint32_t word;
    memcpy(&word, (const unsigned char*)in + i * 4, 4);
    rgba[i * 4 + (bgr ? 2 : 0)] = eight_from_ten(word & 1023u);
    rgba[i * 4 + 1] = eight_from_ten(word >> 10 & 1023u);
    rgba[i * 4 + (bgr ? 0 : 2)] = eight_from_ten(word >> 20 & 1023u);
    rgba[i * 4 + 3] = (unsigned char)((word >> 30) * 85u);
  }
}

int main(int argc, char** argv) {
  context c;
  gpu_image g;
  int width, height, want_width, want_height, channels, bgra, ten_bit, worst;
  unsigned char *input, *want, *got;
  size_t i, pixels, changed;
  VkFormat format;
  if (argc != 7 && argc != 8)
    return fail("usage: bridge_c_test IN.png EXPECTED.png PLUGIN_DIR CHAIN rgba|bgra|a2b10g10r10|a2r10g10b10 "
                "shared|host|native|record [SET]"),
           2;
  input = stbi_load(argv[1], &width, &height, &channels, 4);
  want = stbi_load(argv[2], &want_width, &want_height, &channels, 4);
  if (!input || !want || want_width != width || want_height != height) return fail("could not read the PNGs"), 2;
  bgra = strcmp(argv[5], "bgra") == 0;
  ten_bit = strcmp(argv[5], "a2b10g10r10") == 0 || strcmp(argv[5], "a2r10g10b10") == 0;
  if (strcmp(argv[5], "a2r10g10b10") == 0) format = VK_FORMAT_A2R10G10B10_UNORM_PACK32;
  else if (ten_bit) format = VK_FORMAT_A2B10G10R10_UNORM_PACK32;
  else format = bgra ? VK_FORMAT_B8G8R8A8_UNORM : VK_FORMAT_R8G8B8A8_UNORM;
  pixels = (size_t)width * (size_t)height;
  memset(&c, 0, sizeof c);
  memset(&g, 0, sizeof g);
  keep_driver_mapped();
  if (!make_context(&c) || !make_image(&c, format, (uint32_t)width, (uint32_t)height, &g)) return 1;
  if (ten_bit) pack_ten_bit(input, pixels, format == VK_FORMAT_A2R10G10B10_UNORM_PACK32, g.mapped);
  for (i = 0; i < pixels && !ten_bit; ++i) {
    unsigned char* out = (unsigned char*)g.mapped + i * 4;
    out[0] = input[i * 4 + (bgra ? 2 : 0)];
    out[1] = input[i * 4 + 1];
    out[2] = input[i * 4 + (bgra ? 0 : 2)];
    out[3] = input[i * 4 + 3];
  }
  if (!transfer(&c, &g, 1)) return 1;
  if (!run_bridge(&c, &g, format, argv[3], argv[4], argc == 8 ? argv[7] : NULL, argv[6])) return 1;
  if (!transfer(&c, &g, 0)) return 1;
  /* A 10-bit result is judged at 8 bits, each code to the nearest: the expected picture is 8-bit. */
  got = (unsigned char*)g.mapped;
  if (ten_bit) {
    got = (unsigned char*)malloc(pixels * 4);
    if (!got) return fail("out of memory"), 1;
    unpack_ten_bit(g.mapped, pixels, format == VK_FORMAT_A2R10G10B10_UNORM_PACK32, got);
  }
  worst = compare(got, want, input, pixels, bgra, &changed);
  if (ten_bit) free(got);
  printf("largest difference from the expected picture: %d codes; %lu of %lu pixels changed by the chain\n", worst,
         (unsigned long)changed, (unsigned long)pixels);
  vkDestroyBuffer(c.device, g.buffer, NULL);
  vkFreeMemory(c.device, g.buffer_memory, NULL);
  vkDestroyImage(c.device, g.image, NULL);
  vkFreeMemory(c.device, g.image_memory, NULL);
  vkDestroyCommandPool(c.device, c.pool, NULL);
  vkDestroyDevice(c.device, NULL);
  vkDestroyInstance(c.instance, NULL);
  stbi_image_free(input);
  stbi_image_free(want);
  /* An effect that changed nothing would make a comparison with an unchanged picture pass. */
  if (strcmp(argv[4], "none") != 0 && changed == 0) return fail("the chain changed no pixel"), 1;
  return worst <= 1 ? 0 : 1;
}
