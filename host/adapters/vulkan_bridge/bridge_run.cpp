// pfx_vk_bridge_run: one frame's trip (vulkan_bridge.h), and the bridge's state for the caller.
#include <cstddef>

#include "bridge.hpp"
#include "copy_pass.hpp"
#include "vk_submit.hpp"

namespace pfx::vk {
namespace {

// Blue in the bits where the GL's RGBA8 and RGB10_A2 keep red.
bool is_bgra(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB ||
         format == VK_FORMAT_A2R10G10B10_UNORM_PACK32;
}

bool takes_format(VkFormat format) { return is_eight_bit(format) || is_ten_bit(format); }

// The first pfx_vk_image ended at result_pixels; a caller built against it passes that size.
constexpr size_t kFirstImageSize = offsetof(pfx_vk_image, result_pixels) + sizeof(uint8_t*);

uint32_t image_flags(const pfx_vk_image& image) {
  return image.struct_size >= offsetof(pfx_vk_image, flags) + sizeof image.flags ? image.flags : 0u;
}

// A run that gives up before its work (a bad argument, a chain or a copy in that failed), or a frame
// no effect would change: the caller's semaphores still pass, so its frame goes on as if the
// bridge were not there. A batch with no commands and no fence: it uses nothing of the bridge's
// that must be waited for.
void pass_semaphores(pfx_vk_bridge* bridge, const pfx_vk_image& image) {
  std::string unused;
  bridge->submitted = submit_frame(bridge->functions, bridge->queue, VK_NULL_HANDLE, VK_NULL_HANDLE, image,
                                   VK_PIPELINE_STAGE_TRANSFER_BIT, true, true, &unused);
}

// Makes the go-between for the image's size; when sharing fails, says so once and moves to host
// memory for good.
bool prepare(pfx_vk_bridge* bridge, const pfx_vk_image& image, std::string* error) {
  if (bridge->path == Path::SHARED) {
    int fd = -1;
    uint64_t size = 0;
    std::string why;
    const Between between = bridge->transport->between_for(Path::SHARED, image.format);
    bool ready = bridge->transport->prepare(Path::SHARED, image.width, image.height, between, &fd, &size, &why);
    if (ready && fd >= 0) {
      std::string worker_error;
      if (!bridge->worker->run(
              [&] {
                ready = bridge->gl->shared().import(fd, size, int(image.width), int(image.height), between, &why);
              },
              &worker_error)) {
        ready = false;
        why = worker_error;
      }
    }
    if (ready && fd >= 0)
      bridge->say(0, std::to_string(image.width) + "x" + std::to_string(image.height) +
                         (between.blits ? " frames: Vulkan blits them into the chain's textures and back"
                                        : " frames: copied as they are; the GL turns their rows over"));
    if (ready) return true;
    bridge->say(1, "sharing memory with the GL failed (" + why + "): frames go through host memory from now on");
    bridge->path = Path::HOST;
  }
  int unused_fd = -1;
  uint64_t unused_size = 0;
  return bridge->transport->prepare(Path::HOST, image.width, image.height,
                                    bridge->transport->between_for(Path::HOST, image.format), &unused_fd, &unused_size,
                                    error);
}

double frame_time(pfx_vk_bridge* bridge) {
  if (bridge->frames == 0) bridge->first_run = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - bridge->first_run).count();
}

// Whether the chain would change this frame: it would not with no effect on, or every effect a
// no-op with its values.
bool runs_passes(pfx_vk_bridge* bridge, const pfx_vk_image& image, bool* passes, std::string* error) {
  const double time_seconds = frame_time(bridge);
  bool planned = false;
  std::string worker_error;
  if (!bridge->worker->run(
          [&] {
            planned = bridge->gl->plans_passes(int(image.width), int(image.height), time_seconds, bridge->frames,
                                               passes, error);
          },
          &worker_error)) {
    *error = worker_error;
    return false;
  }
  return planned;
}

bool run_chain(pfx_vk_bridge* bridge, const pfx_vk_image& image, std::string* error) {
  const double time_seconds = frame_time(bridge);
  void* host_bytes = bridge->path == Path::HOST ? bridge->transport->mapped() : nullptr;
  bool ran = false;
  std::string worker_error;
  if (!bridge->worker->run(
          [&] {
            const GlFrame::Readback readback{image.app_pixels, image.result_pixels};
            if (bridge->transport->between().blits) {
              ran = bridge->gl->run_on_layers(int(image.width), int(image.height), bridge->transfer, time_seconds,
                                              bridge->frames, readback, error);
            } else {
              const GlFrame::Texels texels{is_bgra(image.format), is_ten_bit(image.format)};
              ran = bridge->gl->run(host_bytes, int(image.width), int(image.height), texels, bridge->transfer,
                                    time_seconds, bridge->frames, readback, error);
            }
            const host::FrameReport& report = bridge->gl->report();
            bridge->timing = report.timing;
            bridge->times = report.times;
          },
          &worker_error)) {
    *error = worker_error;
    return false;
  }
  ++bridge->frames;
  bridge->gl_waits += 2;
  return ran;
}

// The native chain's work for the image recorded into `commands`, its instances made first where
// the size or format is new; false with *error and the status to return.
pfx_vk_status record_native(pfx_vk_bridge* bridge, VkCommandBuffer commands, const pfx_vk_image& image,
                            double time_seconds, std::string* error) {
  CommandRing& ring = *bridge->ring;
  NativeChain& chain = *bridge->native;
  if (!chain.prepare(bridge->device, image.width, image.height, image.format, [&ring] { ring.wait_idle(); }, error))
    return PFX_VK_CHAIN_FAILED;
  const bool alpha_unused = (image_flags(image) & PFX_VK_IMAGE_ALPHA_UNUSED) != 0;
  return chain.record(commands, image.image, image.layout, alpha_unused, time_seconds, bridge->frames, error)
             ? PFX_VK_OK
             : PFX_VK_CHAIN_FAILED;
}

// One frame on the native path: the effects' commands (between the read-backs asked for) in one
// command buffer, submitted after the image's semaphores and signalling its own. The CPU waits
// only for a read-back, or for a command buffer still in flight (CommandRing).
pfx_vk_status run_native(pfx_vk_bridge* bridge, const pfx_vk_image& image) {
  const double time_seconds = frame_time(bridge);
  const bool reads_back = image.app_pixels || image.result_pixels;
  if (!bridge->native->runs_effects() && !reads_back) {
    ++bridge->frames;
    if (image_flags(image) & PFX_VK_IMAGE_MAY_SKIP) return PFX_VK_OK;
    pass_semaphores(bridge, image);
    return bridge->submitted ? PFX_VK_OK : PFX_VK_VULKAN_FAILED;
  }
  std::string error;
  const auto give_up = [&](pfx_vk_status status) {
    bridge->last_error = error;
    pass_semaphores(bridge, image);
    return status;
  };
  if (reads_back && !bridge->readback)
    bridge->readback = std::make_unique<FrameReadback>(bridge->functions, bridge->device.device,
                                                       bridge->device.physical_device);
  if (reads_back && !bridge->readback->prepare(image.width, image.height, &error)) return give_up(PFX_VK_VULKAN_FAILED);
  CommandRing& ring = *bridge->ring;
  const VkCommandBuffer commands = ring.begin(&error);
  if (!commands) return give_up(PFX_VK_VULKAN_FAILED);
  if (reads_back) bridge->readback->record(commands, image.image, image.layout, false);
  // A chain that fails is not submitted: the next begin() resets the buffer.
  const pfx_vk_status recorded = record_native(bridge, commands, image, time_seconds, &error);
  if (recorded != PFX_VK_OK) return give_up(recorded);
  if (reads_back) bridge->readback->record(commands, image.image, image.layout, true);
  if (!ring.submit(image, &error)) return give_up(PFX_VK_VULKAN_FAILED);
  bridge->submitted = true;
  bridge->ran_passes = bridge->native->runs_effects();
  ++bridge->frames;
  if (reads_back) {
    if (!ring.wait_last(&error)) {
      bridge->last_error = error;
      return PFX_VK_VULKAN_FAILED;
    }
    bridge->readback->hand_over(is_bgra(image.format), image.app_pixels, image.result_pixels);
  }
  return PFX_VK_OK;
}

}  // namespace
}  // namespace pfx::vk

using namespace pfx;

extern "C" PFX_VK_API pfx_vk_status pfx_vk_bridge_run(pfx_vk_bridge* bridge, const pfx_vk_image* image) {
  if (!bridge) return PFX_VK_BAD_ARGUMENT;
  bridge->last_error.clear();
  bridge->ran_passes = false;
  bridge->submitted = false;
  std::string error;
  if (!image || image->struct_size < vk::kFirstImageSize || !image->image || !image->width || !image->height ||
      !vk::takes_format(image->format)) {
    bridge->last_error = "pfx_vk_bridge_run: a null image, a struct_size too small, or a format the bridge does not take";
    if (image && image->struct_size >= vk::kFirstImageSize) vk::pass_semaphores(bridge, *image);
    return PFX_VK_BAD_ARGUMENT;
  }
  if (bridge->native && vk::is_eight_bit(image->format)) return vk::run_native(bridge, *image);
  // The GL path, made now when the bridge took the native one (a 10-bit frame).
  if (!bridge->gl) {
    const pfx_vk_status started = vk::start_gl(bridge, bridge->recipe, &error);
    if (started != PFX_VK_OK) {
      bridge->last_error = error;
      vk::pass_semaphores(bridge, *image);
      return started;
    }
  }
  bool passes = true;
  if (!vk::runs_passes(bridge, *image, &passes, &error)) {
    bridge->last_error = error;
    vk::pass_semaphores(bridge, *image);
    return PFX_VK_CHAIN_FAILED;
  }
  // A frame the chain would not change is left in the image as it is (no copy in, no pass, no copy
  // back) unless the caller wants it read back; with PFX_VK_IMAGE_MAY_SKIP nothing is submitted.
  if (!passes && !image->app_pixels && !image->result_pixels) {
    ++bridge->frames;
    if (vk::image_flags(*image) & PFX_VK_IMAGE_MAY_SKIP) return PFX_VK_OK;
    vk::pass_semaphores(bridge, *image);
    return bridge->submitted ? PFX_VK_OK : PFX_VK_VULKAN_FAILED;
  }
  if (!vk::prepare(bridge, *image, &error) || !bridge->transport->copy_in(*image, &error)) {
    bridge->last_error = error;
    vk::pass_semaphores(bridge, *image);
    return PFX_VK_VULKAN_FAILED;
  }
  const bool ran = vk::run_chain(bridge, *image, &error);
  if (!ran) bridge->last_error = error;
  bridge->ran_passes = ran && passes;
  bridge->submitted = bridge->transport->copy_out(*image, ran && !bridge->dry_run, &error);
  if (!bridge->submitted) {
    bridge->last_error = error;
    return PFX_VK_VULKAN_FAILED;
  }
  return ran ? PFX_VK_OK : PFX_VK_CHAIN_FAILED;
}

extern "C" PFX_VK_API pfx_vk_status pfx_vk_bridge_record(pfx_vk_bridge* bridge, VkCommandBuffer commands,
                                                         const pfx_vk_image* image) {
  if (!bridge) return PFX_VK_BAD_ARGUMENT;
  bridge->last_error.clear();
  bridge->ran_passes = false;
  bridge->submitted = false;
  if (!commands || !image || image->struct_size < vk::kFirstImageSize || !image->image || !image->width ||
      !image->height || !vk::is_eight_bit(image->format)) {
    bridge->last_error = "pfx_vk_bridge_record: a null command buffer or image, a struct_size too small, or an image "
                         "that is not 8-bit";
    return PFX_VK_BAD_ARGUMENT;
  }
  if (!bridge->native) {
    bridge->last_error = "pfx_vk_bridge_record: the chain runs through OpenGL, which records nothing into a command "
                         "buffer (pfx_vk_bridge_run takes it)";
    return PFX_VK_BAD_ARGUMENT;
  }
  const double time_seconds = vk::frame_time(bridge);
  if (bridge->native->runs_effects()) {
    std::string error;
    const pfx_vk_status recorded = vk::record_native(bridge, commands, *image, time_seconds, &error);
    if (recorded != PFX_VK_OK) {
      bridge->last_error = error;
      return recorded;
    }
    bridge->ran_passes = true;
  }
  ++bridge->frames;
  return PFX_VK_OK;
}

extern "C" PFX_VK_API int pfx_vk_bridge_submitted(const pfx_vk_bridge* bridge) {
  return bridge && bridge->submitted ? 1 : 0;
}

extern "C" PFX_VK_API const char* pfx_vk_bridge_path(const pfx_vk_bridge* bridge) {
  if (!bridge) return "";
  if (bridge->native) return "native";
  return bridge->path == vk::Path::SHARED ? "shared memory" : "host memory";
}

extern "C" PFX_VK_API pfx_vk_status pfx_vk_bridge_frame_times(const pfx_vk_bridge* bridge,
                                                              pfx_vk_frame_times* times) {
  if (!bridge || !times || times->struct_size < sizeof(pfx_vk_frame_times)) return PFX_VK_BAD_ARGUMENT;
  // The array lives in the bridge, like the strings it points to, until the next call on it.
  auto& passes = bridge->pass_times;
  passes.clear();
  for (const auto& pass : bridge->times.passes) passes.push_back({pass.effect.c_str(), pass.pass.c_str(), pass.ms});
  times->frame = bridge->times.frame;
  times->timing = bridge->timing.c_str();
  times->total_ms = bridge->times.total_ms;
  times->pass_count = static_cast<uint32_t>(passes.size());
  times->passes = passes.data();
  return PFX_VK_OK;
}

extern "C" PFX_VK_API const char* pfx_vk_bridge_chain(const pfx_vk_bridge* bridge) {
  return bridge ? bridge->chain_text.c_str() : "";
}

extern "C" PFX_VK_API int pfx_vk_bridge_ran_passes(const pfx_vk_bridge* bridge) {
  return bridge && bridge->ran_passes ? 1 : 0;
}

extern "C" PFX_VK_API double pfx_vk_bridge_copy_pass_ms(pfx_vk_bridge* bridge, uint32_t width, uint32_t height) {
  if (!bridge || !width || !height || !bridge->worker) return 0;  // the native path has no GL
  double ms = 0;
  std::string unused;
  bridge->worker->run([&] { ms = gl::median_copy_pass_ms(int(width), int(height), 9); }, &unused);
  return ms;
}

extern "C" PFX_VK_API const char* pfx_vk_bridge_last_error(const pfx_vk_bridge* bridge) {
  return bridge ? bridge->last_error.c_str() : "";
}
