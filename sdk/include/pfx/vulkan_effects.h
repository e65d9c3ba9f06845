/* pfx C ABI v1 — effects that run on a Vulkan device (since 1.7). A plugin whose effects can also
 * run natively on a host's Vulkan device (the FX plugin: every ReShade FX technique) offers this
 * factory beside its pfx.effects/1 one; get_factory(PFX_VULKAN_EFFECTS_FACTORY_ID) returns NULL when
 * it has none. The effects are the same ones, with the same ids and parameters: a host that runs
 * in a Vulkan application (a layer, an engine) uses this kind where every effect of its chain
 * offers it, and keeps the GL kind otherwise.
 *
 * What an instance does: it records the frame's work into a command buffer the host gives and
 * returns. It never submits, waits on the device or a fence, or creates a queue, and it loads every
 * Vulkan function it calls through the host's vkGetInstanceProcAddr and vkGetDeviceProcAddr (a
 * layer passes the next link of its chain). Command buffers one instance recorded must execute in
 * the order they were recorded, on queues of the family the device names; the host destroys an
 * instance only after every command buffer it recorded has completed (a vkDeviceWaitIdle, or the
 * fences of those submissions).
 *
 * Needs Vulkan's headers (Debian: libvulkan-dev); pfx/pfx.h does not include this file. */
#ifndef PFX_VULKAN_EFFECTS_H
#define PFX_VULKAN_EFFECTS_H

#include <vulkan/vulkan.h>

#include "pfx/core.h"
#include "pfx/effect.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PFX_VULKAN_EFFECTS_FACTORY_ID "pfx.vulkan_effects/1"

/* The device an instance runs on. */
typedef struct pfx_vk_device {
  uint32_t struct_size;
  VkInstance instance;
  VkPhysicalDevice physical_device;
  VkDevice device;
  PFN_vkGetInstanceProcAddr get_instance_proc_addr;
  PFN_vkGetDeviceProcAddr get_device_proc_addr;
  /* The family of the queues the command buffers run on: graphics and compute. */
  uint32_t queue_family_index;
  /* The Vulkan version the device was created for (VkApplicationInfo::apiVersion): VK_API_VERSION_1_0
   * when the host does not know. An instance uses nothing newer than it. */
  uint32_t api_version;
} pfx_vk_device;
#define PFX_VK_DEVICE_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_vk_device, api_version)

/* pfx_vk_frame_image.flags */
enum {
  /* The frame's alpha means nothing to the host (a swapchain composited opaque): the instance may
   * leave any alpha, and skips the work of keeping the frame's. */
  PFX_VK_FRAME_ALPHA_UNUSED = 1u << 0
};

/* The frame one recording works on: an image holding an 8-bit display-referred picture (sRGB
 * codes: R8G8B8A8 or B8G8R8A8, UNORM or SRGB), row 0 its top row, with TRANSFER_SRC and
 * TRANSFER_DST usage, of the size and format the instance was created for. */
typedef struct pfx_vk_frame_image {
  uint32_t struct_size;
  VkImage image;
  /* The layout it is in when the recorded commands start, and the one they leave it in. Earlier
   * work on it is waited for (all commands), and later work waits for the instance's. */
  VkImageLayout layout;
  VkImageLayout final_layout;
  uint32_t flags; /* PFX_VK_FRAME_* */
} pfx_vk_frame_image;
#define PFX_VK_FRAME_IMAGE_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_vk_frame_image, flags)

typedef struct pfx_vulkan_effect_factory {
  uint32_t struct_size;
  /* Whether effect `effect_id` of this plugin runs on Vulkan: 1 or 0. Any thread. */
  int32_t (*supports)(const char* effect_id);
  /* An instance of `effect_id` on `device`, for frames of width x height in `format`. The host
   * creates another when the size or format changes. Any thread the host uses for the device, not
   * two at once for one device. PFX_OK; PFX_UNSUPPORTED when the effect needs what the plugin's
   * Vulkan side lacks, PFX_ERROR when it fails (a file that no longer compiles, a Vulkan call that
   * failed), each with the reason in `error` (NUL-terminated, cut to error_size). */
  pfx_status (*create)(const pfx_host* host, const char* effect_id, const pfx_vk_device* device, uint32_t width, uint32_t height,
                       VkFormat format, void** out_instance, char* error, uint32_t error_size);
  /* Records one frame into `commands`: a primary command buffer being recorded, outside a render
   * pass, for a queue of the device's family. `params` holds the effect's parameter values, one
   * per parameter of its descriptor, as for pfx.effects/1 (NULL for an effect without parameters);
   * `frame` gives the time and the frame
   * number (its depth and G-buffer are not read). PFX_OK, or PFX_ERROR with nothing recorded
   * that would change the image (the frame passes through). */
  pfx_status (*record)(void* instance, VkCommandBuffer commands, const pfx_vk_frame_image* image, const pfx_frame* frame,
                       const pfx_value* params);
  /* After every command buffer the instance recorded has completed. */
  void (*destroy)(void* instance);
  /* Appended after destroy: a host checks PFX_STRUCT_HAS before calling it, and it may be NULL (a
   * factory without it still pairs: PFX_VULKAN_EFFECT_FACTORY_MIN_SIZE ends at destroy). As
   * create, with preprocessor definitions for an effect made from a source file, in the form and
   * with the meaning of pfx.sources/1's set_definitions ("NAME=VALUE,NAME2=VALUE2,FLAG"; NULL or
   * "" sets none). An instance keeps its definitions: for others the host destroys it and creates
   * another, as for another size. PFX_INVALID_ARGUMENT, with the reason in `error`, for a
   * malformed list. */
  pfx_status (*create_with_definitions)(const pfx_host* host, const char* effect_id, const pfx_vk_device* device,
                                        uint32_t width, uint32_t height, VkFormat format, const char* definitions,
                                        void** out_instance, char* error, uint32_t error_size); /* since 1.8 */
} pfx_vulkan_effect_factory;
#define PFX_VULKAN_EFFECT_FACTORY_MIN_SIZE PFX_STRUCT_SIZE_THROUGH(pfx_vulkan_effect_factory, destroy)

#ifdef __cplusplus
}
#endif
#endif /* PFX_VULKAN_EFFECTS_H */
