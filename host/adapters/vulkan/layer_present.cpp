// vkQueuePresentKHR as the layer sees it: each presented image goes through the bridge (which waits
// on the application's semaphores and signals the image's own), and the present waits on those.
// Any failure turns the device into a pass-through, said once.
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <vector>

#include "layer_calls.hpp"
#include "layer_capture.hpp"
#include "layer_reports.hpp"
#include "layer_state.hpp"
#include "process_memory.hpp"

namespace pfx::vulkan_layer {
namespace {

void log_from_bridge(void*, int level, const char* message) {
  log_line(std::string(level >= 2 ? "error: " : level == 1 ? "warning: " : "") + message);
}

// What the bridge of `queue` is made with: the device, and pfx-inject's settings.
pfx_vk_bridge_desc bridge_desc(const Device& d, VkQueue queue, uint32_t family) {
  const BridgeSettings& settings = bridge_settings();
  pfx_vk_bridge_desc desc{};
  desc.struct_size = sizeof desc;
  desc.instance = d.instance;
  desc.physical_device = d.physical_device;
  desc.device = d.handle;
  desc.get_instance_proc_addr = d.next_instance_proc;
  desc.get_device_proc_addr = d.next_get_proc;
  desc.queue = queue;
  desc.queue_family_index = family;
  desc.device_has_bridge_extensions = d.bridge_extensions;
  desc.chain = settings.chain;
  desc.set = settings.set;
  desc.preset = settings.preset;
  desc.transfer = settings.transfer;
  desc.plugin_path = settings.plugin_path;
  // Settings made by hand: what does not apply is named and left out, the rest runs (pfx-inject's
  // rule for OpenGL applications).
  desc.flags = PFX_VK_LEAVE_OUT_BAD_SETTINGS | (layer_inject_settings().dry_run ? PFX_VK_DRY_RUN : 0u) |
               (layer_inject_settings().timings_file.empty() ? 0u : PFX_VK_TIME_PASSES);
  desc.log = log_from_bridge;
  desc.set_device_loader_data = d.set_loader_data;
  return desc;
}

// A preset edited while the application runs (by hand, or in pfx-inject --panel's pfx-view)
// applies to every bridge of the device; one that does not apply leaves the chain as it was.
void reread_preset_if_changed(Device* d) {
  if (d->bridges.empty() || !d->preset_watch || !d->preset_watch->changed()) return;
  for (const auto& [queue, bridge] : d->bridges) {
    const pfx_vk_bridge_desc desc = bridge_desc(*d, queue, d->queue_families.at(queue));
    char error[1024] = "";
    if (pfx_vk_bridge_update(bridge, &desc, error, sizeof error) != PFX_VK_OK)
      log_line(std::string("the changed preset could not be applied (") + error + "); the previous chain keeps running");
  }
}

// The bridge of the presenting queue, made at its first present; null (and the device a
// pass-through) when it cannot be.
pfx_vk_bridge* bridge_for(Device* d, VkQueue queue) {
  auto found = d->bridges.find(queue);
  if (found != d->bridges.end()) return found->second;
  const auto family = d->queue_families.find(queue);
  if (family == d->queue_families.end()) {
    log_once("unknown queue", "a present on a queue the layer did not see handed out: frames pass through");
    d->failed = true;
    return nullptr;
  }
  if (!d->preset_watch) {
    const char* preset = bridge_settings().preset;
    d->preset_watch = std::make_unique<inject::PresetWatch>(preset ? preset : "");
  }
  const pfx_vk_bridge_desc desc = bridge_desc(*d, queue, family->second);
  pfx_vk_bridge* bridge = nullptr;
  char error[1024] = "";
  if (pfx_vk_bridge_create(&desc, &bridge, error, sizeof error) != PFX_VK_OK) {
    log_line(std::string("frames pass through: ") + error);
    d->failed = true;
    return nullptr;
  }
  d->bridges[queue] = bridge;
  return bridge;
}

// Why a capture of a device whose chain failed is not written, on the frame it failed and after.
constexpr const char* kChainFailed = "the chain failed and frames pass through";

// Counted from 1 over every swapchain of the process, as pfx-inject counts over every context.
std::atomic<uint64_t> presented{0};

// Runs the image through the bridge (with the captures asked for this frame, named for the present's
// swapchain_index-th swapchain); false when the device must pass through from now on.
// pfx_vk_bridge_submitted then says whether the image's semaphore will be signalled.
bool run_image(pfx_vk_bridge* bridge, pfx_vk_image* image, uint64_t frame, uint32_t swapchain_index) {
  std::vector<std::string> prefixes = capture_prefixes_for(frame);
  for (auto& prefix : prefixes) prefix += swapchain_suffix(swapchain_index);
  std::vector<uint8_t> app, result;
  if (!prefixes.empty()) {
    app.resize(size_t(image->width) * image->height * 4);
    result.resize(app.size());
    image->app_pixels = app.data();
    image->result_pixels = result.data();
  }
  // A frame the chain would not change adds nothing to the application's queue.
  image->flags |= PFX_VK_IMAGE_MAY_SKIP;
  const pfx_vk_status status = pfx_vk_bridge_run(bridge, image);
  if (status != PFX_VK_OK) {
    log_line("frame " + std::to_string(frame) + ": frames pass through from now on: " +
             pfx_vk_bridge_last_error(bridge));
    say_captures_skipped(frame, swapchain_index, kChainFailed);
    return false;
  }
  // A dry run presents the application's frame: that is what PREFIX.png shows.
  const bool dry_run = layer_inject_settings().dry_run;
  for (const auto& prefix : prefixes) write_capture(prefix, image->width, image->height, app, dry_run ? app : result);
  report_run(bridge, *image, frame);
  return true;
}

// The application's work in flight finished, so that its exit handlers (and those of the layers
// around pfx) destroy nothing a queue still uses.
void idle_every_device() {
  std::lock_guard<std::mutex> lock(state().mutex);
  for (const auto& [key, device] : state().devices) device->DeviceWaitIdle(device->handle);
}

}  // namespace

VKAPI_ATTR VkResult VKAPI_CALL QueuePresentKHR(VkQueue queue, const VkPresentInfoKHR* info) {
  std::unique_lock<std::mutex> lock(state().mutex);
  Device* d = find_device(key_of(queue));
  if (!d) return VK_ERROR_DEVICE_LOST;  // a queue of no device the loader gave us cannot be presented on
  const uint64_t frame = ++presented;
  // Frames before --from-frame (a splash screen) and every frame of --bench's "application alone"
  // pass through untouched, as in OpenGL applications.
  const bool before_start = frame < layer_inject_settings().from_frame;
  const bool untouched = before_start || layer_inject_settings().bypass;
  if (before_start) say_captures_skipped(frame, 0, "frames before --from-frame pass through");
  else if (d->failed && !untouched) say_captures_skipped(frame, 0, kChainFailed);
  if (!d->failed && !untouched) reread_preset_if_changed(d);
  // What the present waits on: for each image the bridge submitted work for, the image's own
  // semaphore (that work waited on the application's); the application's semaphores where no
  // submission took them, as in a frame the chain leaves alone.
  std::vector<VkSemaphore> waits;
  bool application_waits_taken = info->waitSemaphoreCount == 0;
  for (uint32_t i = 0; i < info->swapchainCount && !d->failed && !untouched; ++i) {
    auto found = d->swapchains.find(info->pSwapchains[i]);
    const uint32_t index = info->pImageIndices[i];
    if (found == d->swapchains.end() || !found->second->usable || index >= found->second->images.size()) {
      say_captures_skipped(frame, i, "this swapchain's frames pass through");
      continue;
    }
    const Swapchain& s = *found->second;
    pfx_vk_bridge* bridge = bridge_for(d, queue);
    if (!bridge) {
      say_captures_skipped(frame, i, "the chain could not be made");
      break;
    }
    pfx_vk_image image{};
    image.struct_size = sizeof image;
    image.image = s.images[index];
    image.format = s.format;
    image.width = s.extent.width;
    image.height = s.extent.height;
    image.layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    if (s.opaque) image.flags = PFX_VK_IMAGE_ALPHA_UNUSED;
    if (!application_waits_taken) {  // waited on once, by the first submission
      image.wait_semaphore_count = info->waitSemaphoreCount;
      image.wait_semaphores = info->pWaitSemaphores;
    }
    image.signal_semaphore = s.done[index];
    if (!run_image(bridge, &image, frame, i)) d->failed = true;
    if (pfx_vk_bridge_submitted(bridge)) {
      application_waits_taken = true;
      waits.push_back(s.done[index]);
    }
  }
  if (!application_waits_taken)
    waits.insert(waits.begin(), info->pWaitSemaphores, info->pWaitSemaphores + info->waitSemaphoreCount);
  VkPresentInfoKHR ours = *info;
  ours.waitSemaphoreCount = static_cast<uint32_t>(waits.size());
  ours.pWaitSemaphores = waits.data();
  const VkResult result = d->QueuePresentKHR(queue, &ours);
  report_present();
  lock.unlock();  // the application's exit handlers may destroy its device through the layer
  const auto& report_at = layer_inject_settings().resources_at;
  if (std::find(report_at.begin(), report_at.end(), frame) != report_at.end())
    log_line("frame " + std::to_string(frame) + ": resident memory " + std::to_string(inject::resident_kib()) +
             " KiB; heap in use " + std::to_string(inject::heap_bytes_in_use()) + " bytes");
  if (frame == quit_after()) {
    log_line("frame " + std::to_string(frame) + ": quitting, as asked");
    idle_every_device();
    {
      std::lock_guard<std::mutex> relock(state().mutex);
      write_bench_stats();
    }  // released: the application's exit handlers may come back through the layer
    std::exit(0);
  }
  return result;
}

}  // namespace pfx::vulkan_layer
