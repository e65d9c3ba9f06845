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

// Counted from 1 over every swapchain of the process, as pfx-inject counts over every context.
std::atomic<uint64_t> presented{0};

// Runs the image through the bridge (with the captures asked for this frame, named for the present's
// swapchain_index-th swapchain); false when the device must pass through from now on. The image's
// semaphore is signalled either way.
bool run_image(pfx_vk_bridge* bridge, pfx_vk_image* image, uint64_t frame, uint32_t swapchain_index) {
  std::vector<std::string> prefixes = capture_prefixes_for(frame);
  // A present of several swapchains (an application with several windows): PREFIX for the first,
  // PREFIX-2 for the second...
  if (swapchain_index > 0)
    for (auto& prefix : prefixes) prefix += "-" + std::to_string(swapchain_index + 1);
  std::vector<uint8_t> app, result;
  if (!prefixes.empty()) {
    app.resize(size_t(image->width) * image->height * 4);
    result.resize(app.size());
    image->app_pixels = app.data();
    image->result_pixels = result.data();
  }
  const pfx_vk_status status = pfx_vk_bridge_run(bridge, image);
  if (status != PFX_VK_OK) {
    log_line("frame " + std::to_string(frame) + ": frames pass through from now on: " +
             pfx_vk_bridge_last_error(bridge));
    return false;
  }
  // A dry run presents the application's frame: that is what PREFIX.png shows.
  const bool dry_run = layer_inject_settings().dry_run;
  for (const auto& prefix : prefixes) write_capture(prefix, image->width, image->height, app, dry_run ? app : result);
  report_run(bridge, *image, frame);
  return true;
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
  if (before_start)
    for (const auto& prefix : capture_prefixes_for(frame))
      log_line("frame " + std::to_string(frame) + ": capture " + prefix +
               " not written: frames before --from-frame pass through");
  if (!d->failed && !untouched) reread_preset_if_changed(d);
  std::vector<VkSemaphore> waits;
  for (uint32_t i = 0; i < info->swapchainCount && !d->failed && !untouched; ++i) {
    auto found = d->swapchains.find(info->pSwapchains[i]);
    if (found == d->swapchains.end() || !found->second->usable) continue;
    const Swapchain& s = *found->second;
    const uint32_t index = info->pImageIndices[i];
    if (index >= s.images.size()) continue;
    pfx_vk_bridge* bridge = bridge_for(d, queue);
    if (!bridge) break;
    pfx_vk_image image{};
    image.struct_size = sizeof image;
    image.image = s.images[index];
    image.format = s.format;
    image.width = s.extent.width;
    image.height = s.extent.height;
    image.layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    if (waits.empty()) {  // the application's semaphores, waited on once, by the first image's copy
      image.wait_semaphore_count = info->waitSemaphoreCount;
      image.wait_semaphores = info->pWaitSemaphores;
    }
    image.signal_semaphore = s.done[index];
    if (!run_image(bridge, &image, frame, i)) d->failed = true;
    // Whatever happened, the bridge waited on the semaphores and signalled the image's own.
    waits.push_back(s.done[index]);
  }
  VkResult result = VK_SUCCESS;
  if (waits.empty()) {
    result = d->QueuePresentKHR(queue, info);
  } else {
    VkPresentInfoKHR ours = *info;
    ours.waitSemaphoreCount = static_cast<uint32_t>(waits.size());
    ours.pWaitSemaphores = waits.data();
    result = d->QueuePresentKHR(queue, &ours);
  }
  report_present();
  lock.unlock();  // the application's exit handlers may destroy its device through the layer
  const auto& report_at = layer_inject_settings().resources_at;
  if (std::find(report_at.begin(), report_at.end(), frame) != report_at.end())
    log_line("frame " + std::to_string(frame) + ": resident memory " + std::to_string(inject::resident_kib()) +
             " KiB; heap in use " + std::to_string(inject::heap_bytes_in_use()) + " bytes");
  if (frame == quit_after()) {
    log_line("frame " + std::to_string(frame) + ": quitting, as asked");
    {
      std::lock_guard<std::mutex> relock(state().mutex);
      write_bench_stats();
    }  // released: the application's exit handlers may come back through the layer
    std::exit(0);
  }
  return result;
}

}  // namespace pfx::vulkan_layer
