/* pfx's Vulkan bridge: runs a pfx chain over a VkImage of the caller's (docs/sdk.md, "Vulkan").
 *
 * Plain C99. Link libpfxvulkan. Frames take one of two paths, chosen from the chain:
 *
 * Native: where every effect of the chain runs on Vulkan (its plugin offers pfx.vulkan_effects/1,
 * pfx/vulkan_effects.h: the FX plugin's ReShade FX effects do), the bridge records the effects'
 * passes over the image itself into a command buffer of its own and submits it on the caller's
 * queue, after the image's wait semaphores and signalling its semaphore. No OpenGL context is made,
 * nothing is copied, and the CPU waits for nothing (but a command buffer of four frames before
 * that has not completed, or a read-back the caller asks for). 8-bit images only; a 10-bit one
 * takes the GL path.
 *
 * Through OpenGL, otherwise: the bridge owns an OpenGL 4.5 context on a thread of its own (EGL,
 * never the caller's GL), copies the image into memory that context shares with the Vulkan device
 * (VK_KHR_external_memory_fd + GL_EXT_memory_object_fd), runs the chain there, and copies the
 * result back into the image. Where sharing is not offered (an extension missing, the GL device's
 * UUIDs not those of the Vulkan device) or is switched off, it goes through host memory instead:
 * the same pixels, slower. Either way the two APIs are ordered by waiting for a fence on the Vulkan
 * side and for the GL to finish on the other. A dry run, pass times, preprocessor definitions from
 * a preset for a plugin whose Vulkan factory takes none (older than ABI 1.8), PFX_VK_GL_PATH and
 * PFX_VK_NATIVE=0 in the environment keep a chain on this path.
 *
 * The image holds an 8- or 10-bit display-referred frame (what a swapchain image holds): the
 * effects start at their display-referred defaults. On the GL path it is decoded to linear light
 * and the result encoded back; FX effects read and write the 8-bit codes as they are on both
 * paths. Row 0 of the image is its top row, as Vulkan presents it.
 *
 * Growth: every struct starts with struct_size; later versions only append fields, and a reader
 * reads a field only when struct_size covers it (the rule of pfx/core.h). */
#ifndef PFX_VULKAN_BRIDGE_H
#define PFX_VULKAN_BRIDGE_H

#include <stddef.h>
#include <stdint.h>

#include <vulkan/vulkan.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(PFX_VULKAN_BUILDING)
#define PFX_VK_API __attribute__((visibility("default")))
#else
#define PFX_VK_API
#endif

typedef enum pfx_vk_status {
  PFX_VK_OK = 0,
  PFX_VK_BAD_ARGUMENT = 1,   /* a null pointer, a struct_size too small, a format the bridge does not take */
  PFX_VK_BAD_SETTINGS = 2,   /* the chain, an assignment or the preset does not apply */
  PFX_VK_NO_GL = 3,          /* no OpenGL 4.5 context could be made */
  PFX_VK_VULKAN_FAILED = 4,  /* a Vulkan call failed (allocation, submission, a lost device) */
  PFX_VK_CHAIN_FAILED = 5    /* an effect or a pass failed; the image was left as it was */
} pfx_vk_status;

/* Flags of pfx_vk_bridge_desc. */
#define PFX_VK_FORCE_HOST_MEMORY 0x1u /* never share memory; also forced by PFX_VK_HOST_MEMORY=1 */
/* An effect of the chain, an assignment or a preset that does not apply is left out, with a warning
 * ("ignored chain: ...") in the log, and the rest runs, as pfx-inject treats settings made by hand;
 * without it pfx_vk_bridge_create fails with PFX_VK_BAD_SETTINGS. A bad transfer fails either way. */
#define PFX_VK_LEAVE_OUT_BAD_SETTINGS 0x2u
/* Runs the chain on every frame as usual (result_pixels receives its result) but leaves the image
 * as it came, as pfx-inject --dry-run does: to see what the chain costs, or to compare. */
#define PFX_VK_DRY_RUN 0x4u
/* Times every pass for pfx_vk_bridge_frame_times: GPU timestamps where the GL has trustworthy ones,
 * glFinish and a clock on a software renderer (which then waits for each pass). */
#define PFX_VK_TIME_PASSES 0x8u
/* Always the GL path, even for a chain that could run natively (to compare the two). */
#define PFX_VK_GL_PATH 0x10u

/* The log callback: level 0 information, 1 warning, 2 error. Called on any thread. */
typedef void (*pfx_vk_log_fn)(void* user, int level, const char* message);

typedef struct pfx_vk_bridge_desc {
  uint32_t struct_size; /* sizeof(pfx_vk_bridge_desc) */
  /* The device the images belong to. Functions are looked up through the two loaders given, so a
   * Vulkan layer can hand the next layer's. */
  VkInstance instance;
  VkPhysicalDevice physical_device;
  VkDevice device;
  PFN_vkGetInstanceProcAddr get_instance_proc_addr;
  PFN_vkGetDeviceProcAddr get_device_proc_addr;
  /* The queue the bridge submits its work to, and its family (graphics and compute for the native
   * path; any graphics or compute queue does transfers for the GL path). The caller does not use the queue from another thread during
   * pfx_vk_bridge_run, as Vulkan asks of every queue submission. */
  VkQueue queue;
  uint32_t queue_family_index;
  /* Whether the device was created with every extension pfx_vk_bridge_device_extensions lists:
   * without them the bridge takes the host-memory path. */
  int device_has_bridge_extensions;
  /* The chain, as pfx-render's options: effect ids separated by ',' ("bloom,dof"), "none" for no
   * effect, "" for the preset's chain (no effect without a preset), NULL for the preset's chain or
   * else pfx-inject's default chain: every effect found that needs nothing but colour, in pfx's
   * order (those left out are logged). */
  const char* chain;
  const char* set;          /* "effect.param=value" assignments separated by ';', or NULL */
  const char* preset;       /* a pfx-view preset file, or NULL */
  const char* transfer;     /* "srgb" (NULL: the default) or "linear": how the 8-bit values relate to light */
  const char* plugin_path;  /* plugin folders separated by ':'; NULL: the folder beside libpfxvulkan and PFX_PLUGIN_PATH */
  uint32_t flags;           /* PFX_VK_FORCE_HOST_MEMORY, PFX_VK_LEAVE_OUT_BAD_SETTINGS, PFX_VK_DRY_RUN,
                               PFX_VK_TIME_PASSES, PFX_VK_GL_PATH */
  pfx_vk_log_fn log;        /* NULL: messages go nowhere */
  void* log_user;
  /* For a Vulkan layer: the loader's vkSetDeviceLoaderData (vk_layer.h), which the bridge calls on
   * the command buffers it allocates so the layers below it can dispatch them. NULL for an engine. */
  VkResult(VKAPI_PTR* set_device_loader_data)(VkDevice device, void* object);
} pfx_vk_bridge_desc;

typedef struct pfx_vk_bridge pfx_vk_bridge;

/* The device extensions the shared-memory path needs; a layer adds them when the application
 * creates its device. *count gets their number. */
PFX_VK_API const char* const* pfx_vk_bridge_device_extensions(uint32_t* count);

/* Loads the plugins, checks the settings and chooses the path (the log says which, and why not
 * the native one); the GL path starts its GL thread. The effects compile at the first run. On failure *out is NULL and, when error is not NULL, error (of error_size bytes) says why. */
PFX_VK_API pfx_vk_status pfx_vk_bridge_create(const pfx_vk_bridge_desc* desc, pfx_vk_bridge** out, char* error,
                                              size_t error_size);
/* New settings for a running bridge, such as a preset file edited while frames run: desc's chain,
 * set, preset, transfer and flags (PFX_VK_FORCE_HOST_MEMORY aside), read as pfx_vk_bridge_create reads them (its other members are
 * not read: the device, queue and plugins stay). The new chain takes the path it allows, and the
 * log says when that changes. When the chain names the same effects in the same
 * order only values and on/off flags change and no effect is created again; otherwise the effects
 * are made anew (their programs compile now). All or nothing: on failure the chain that ran keeps
 * running and error says why; a preset that does not read or apply fails it even with
 * PFX_VK_LEAVE_OUT_BAD_SETTINGS. The log gets "settings applied: chain ...". Not during a
 * pfx_vk_bridge_run of the same bridge. */
PFX_VK_API pfx_vk_status pfx_vk_bridge_update(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc* desc, char* error,
                                              size_t error_size);
/* Waits for the bridge's work on the device to end and frees everything it made. NULL is a no-op. */
PFX_VK_API void pfx_vk_bridge_destroy(pfx_vk_bridge* bridge);

typedef struct pfx_vk_image {
  uint32_t struct_size; /* sizeof(pfx_vk_image) */
  VkImage image;        /* 2D, one layer, one level, usage TRANSFER_SRC and TRANSFER_DST, not multisampled */
  /* B8G8R8A8 or R8G8B8A8, UNORM or SRGB (the bytes are read as they are: both are display-referred
   * 8-bit values), or A2B10G10R10_UNORM_PACK32 or A2R10G10B10_UNORM_PACK32 (display-referred 10-bit
   * values, sRGB-encoded like the 8-bit ones). */
  VkFormat format;
  uint32_t width, height;
  VkImageLayout layout; /* the layout it is in, and will be left in (PRESENT_SRC_KHR for a swapchain image) */
  /* Binary semaphores to wait on before the image is read (the application's rendering), with the
   * stages that wait (NULL: TRANSFER for each on the GL path, every stage on the native one). */
  uint32_t wait_semaphore_count;
  const VkSemaphore* wait_semaphores;
  const VkPipelineStageFlags* wait_stages;
  /* Signalled when the result is in the image; VK_NULL_HANDLE: none. Work the caller submits to the
   * same queue afterwards sees the result anyway (the bridge's last barrier covers all commands). */
  VkSemaphore signal_semaphore;
  /* When not NULL, width * height * 4 bytes that receive the image as it came (app_pixels) and as
   * it goes back (result_pixels): R, G, B, A whatever the format, row 0 the top row. For captures
   * and tests; each costs a read-back. */
  uint8_t* app_pixels;
  uint8_t* result_pixels;
  /* Added after result_pixels (read only when struct_size covers it): PFX_VK_IMAGE_MAY_SKIP,
   * PFX_VK_IMAGE_ALPHA_UNUSED. */
  uint32_t flags;
} pfx_vk_image;

/* Flags of pfx_vk_image. A frame the chain would not change (below) submits nothing at all: the
 * bridge neither waits on wait_semaphores nor signals signal_semaphore, pfx_vk_bridge_submitted
 * returns 0, and the caller presents (or goes on) on its own semaphores. Without it such a frame
 * still submits an empty batch that waits and signals. For a layer, whose idle chain then adds
 * nothing to the application's queue. */
#define PFX_VK_IMAGE_MAY_SKIP 0x1u
/* The image's alpha means nothing to the caller (a swapchain composited opaque): the native path
 * may leave any alpha there, and skips the work of keeping it. */
#define PFX_VK_IMAGE_ALPHA_UNUSED 0x2u

/* Runs the chain over the image (the N-th call is frame N - 1 for effects that animate) and submits
 * the copy of the result back. A frame the chain would not change (no effect on, or every effect a
 * no-op with its values) is left in the image as it is, with nothing copied either way, unless
 * app_pixels or result_pixels ask for a read-back. On failure the image holds what it held (the copy back is not made),
 * wait_semaphores are still waited on and signal_semaphore still signalled, so the caller can go on
 * as if the bridge were not there (pfx_vk_bridge_submitted says when even that submission failed). */
PFX_VK_API pfx_vk_status pfx_vk_bridge_run(pfx_vk_bridge* bridge, const pfx_vk_image* image);
/* The native path's other way in, for an engine that submits its own work: records the chain's
 * work over the image into `commands`, a primary command buffer the caller is recording (outside a
 * render pass) for a queue of desc.queue_family_index, and returns; the caller submits it, with
 * its own semaphores and fence, and the bridge submits and waits for nothing. The image is as for
 * pfx_vk_bridge_run, 8-bit only; its semaphores, flags, app_pixels and result_pixels are not read.
 * The buffers recorded must execute in the order they were recorded, and have completed before the
 * next pfx_vk_bridge_update that changes the chain's effects, a call with an image of a fifth size
 * or format (the bridge keeps the effects of four), or pfx_vk_bridge_destroy: the effects they
 * used are freed then. PFX_VK_OK (nothing recorded
 * when no effect is on); PFX_VK_BAD_ARGUMENT when the chain does not run natively
 * (pfx_vk_bridge_path is not "native") or the image is not 8-bit; PFX_VK_CHAIN_FAILED when an
 * effect could not be made or record: what was recorded before it is the whole work of the
 * effects before it, so the buffer may still be submitted. */
PFX_VK_API pfx_vk_status pfx_vk_bridge_record(pfx_vk_bridge* bridge, VkCommandBuffer commands,
                                              const pfx_vk_image* image);
/* Whether the last pfx_vk_bridge_run submitted the work that signals the image's signal_semaphore
 * (having waited on its wait_semaphores): 1 as a rule, and the caller waits on signal_semaphore;
 * 0 for a frame left alone under PFX_VK_IMAGE_MAY_SKIP, whose semaphores are untouched (the caller
 * waits on its own wait_semaphores), or when a submission itself failed (a lost device). */
PFX_VK_API int pfx_vk_bridge_submitted(const pfx_vk_bridge* bridge);

/* "native", "shared memory" or "host memory": the path 8-bit frames take (on the GL path: the one
 * the last run took; before the first run, the one the next will try). */
PFX_VK_API const char* pfx_vk_bridge_path(const pfx_vk_bridge* bridge);
/* The chain that runs, as pfx-inject's log names it: effect ids in order, those switched off marked
 * ("glare,bloom (off)"), or "none". Valid until the next call on the bridge. */
PFX_VK_API const char* pfx_vk_bridge_chain(const pfx_vk_bridge* bridge);
/* Whether the last pfx_vk_bridge_run ran any pass of the chain: 0 when it left the image as it was
 * (nothing on, every effect a no-op) or failed. */
PFX_VK_API int pfx_vk_bridge_ran_passes(const pfx_vk_bridge* bridge);
/* Times a full-frame copy pass between two RGBA16F textures of that size on the bridge's GL context
 * (the median of 9, each with glFinish around it and a clock): the unit pfx's benchmarks give costs
 * in, measured where the chain runs. 0 when it cannot be measured (the native path has no GL). Not during a pfx_vk_bridge_run of
 * the same bridge. */
PFX_VK_API double pfx_vk_bridge_copy_pass_ms(pfx_vk_bridge* bridge, uint32_t width, uint32_t height);
/* One pass's time in pfx_vk_frame_times. */
typedef struct pfx_vk_pass_time {
  const char* effect; /* the effect's id in the chain */
  const char* pass;   /* the pass's name, as the effect declares it */
  double ms;
} pfx_vk_pass_time;
typedef struct pfx_vk_frame_times {
  uint32_t struct_size;            /* sizeof(pfx_vk_frame_times), set by the caller */
  uint64_t frame;                  /* the run they were measured in, from 1; 0: none yet */
  const char* timing;              /* "gpu-timestamps", "finish+clock" or "off" (no PFX_VK_TIME_PASSES) */
  double total_ms;                 /* the passes together */
  uint32_t pass_count;
  const pfx_vk_pass_time* passes;  /* pass_count passes, in the order they ran */
} pfx_vk_frame_times;
/* With PFX_VK_TIME_PASSES: the times of the newest run whose passes are all timed (GPU timestamps
 * arrive a frame or two late, never waited for). The strings and the array stay valid until the
 * next call on the bridge. */
PFX_VK_API pfx_vk_status pfx_vk_bridge_frame_times(const pfx_vk_bridge* bridge, pfx_vk_frame_times* times);
/* What the last failure was, or "" (valid until the next call on the bridge). */
PFX_VK_API const char* pfx_vk_bridge_last_error(const pfx_vk_bridge* bridge);

#ifdef __cplusplus
}
#endif

#endif /* PFX_VULKAN_BRIDGE_H */
