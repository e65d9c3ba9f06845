// The two paths a bridge's frames take (vulkan_bridge.h): native, where every effect of the chain
// records its passes on the caller's device; through OpenGL otherwise, on a GL thread of the
// bridge's own with the frame copied there and back. Each is made when it is first taken.
#include <cstdlib>
#include <cstring>

#include "bridge.hpp"
#include "timing_choice.hpp"

namespace pfx::vk {
namespace {

bool forced_host_memory(uint32_t flags) {
  const char* variable = std::getenv("PFX_VK_HOST_MEMORY");
  return (flags & PFX_VK_FORCE_HOST_MEMORY) || (variable && std::strcmp(variable, "1") == 0);
}

// Whether GL and Vulkan can share memory, and why not: the GL side is asked on the worker.
Path choose_memory(pfx_vk_bridge* bridge, std::string* why) {
  if (forced_host_memory(bridge->flags)) {
    *why = "host memory asked for";
    return Path::HOST;
  }
  if (!bridge->functions.GetMemoryFdKHR) {
    *why = "the Vulkan device was made without VK_KHR_external_memory_fd";
    return Path::HOST;
  }
  if (!bridge->functions.GetPhysicalDeviceProperties2) {
    *why = "the Vulkan instance gives no vkGetPhysicalDeviceProperties2";
    return Path::HOST;
  }
  VkPhysicalDeviceIDProperties ids{};
  ids.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES;
  VkPhysicalDeviceProperties2 properties{};
  properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  properties.pNext = &ids;
  bridge->functions.GetPhysicalDeviceProperties2(bridge->device.physical_device, &properties);
  bool shares = false;
  std::string worker_error;
  if (!bridge->worker->run([&] { shares = bridge->gl->shared().check(ids.deviceUUID, ids.driverUUID, why); },
                           &worker_error))
    *why = worker_error;
  return shares ? Path::SHARED : Path::HOST;
}

// The GL thread's chain made from the fitted recipe, or handed it when it is made.
pfx_vk_status make_gl_chain(pfx_vk_bridge* bridge, const app::ChainRecipe& fitted, std::string* error) {
  const bool fresh = !bridge->gl;
  bool made = false;
  std::string chain;
  if (!bridge->worker->run(
          [&] {
            if (fresh) bridge->gl = std::make_unique<GlFrame>();
            made = fresh ? bridge->gl->create(*bridge->registry, fitted, error)
                         : bridge->gl->update(*bridge->registry, fitted, error);
            if (!made) {
              if (fresh) bridge->gl.reset();
              return;
            }
            chain = bridge->gl->chain_text();
            bridge->gl->set_timing(timing_for(bridge, bridge->flags));
          },
          error))
    return PFX_VK_NO_GL;
  if (!made) return PFX_VK_CHAIN_FAILED;
  bridge->chain_text = chain;
  if (!fresh) return PFX_VK_OK;
  std::string why;
  bridge->path = choose_memory(bridge, &why);
  bridge->say(0, bridge->path == Path::SHARED
                     ? "frames go through memory shared with the GL (" + bridge->worker->renderer() + ")"
                     : "frames go through host memory: " + why);
  return PFX_VK_OK;
}

}  // namespace

bool native_wanted(const pfx_vk_bridge* bridge, uint32_t flags, const app::ChainRecipe& recipe, std::string* why) {
  const char* variable = std::getenv("PFX_VK_NATIVE");
  if ((flags & PFX_VK_GL_PATH) || (variable && std::strcmp(variable, "0") == 0)) {
    *why = "the GL path was asked for";
    return false;
  }
  if (flags & PFX_VK_DRY_RUN) {
    *why = "a dry run keeps the image as it came, which only the GL path does";
    return false;
  }
  if (flags & PFX_VK_TIME_PASSES) {
    *why = "pass times were asked for, which only the GL path measures";
    return false;
  }
  return NativeChain::takes(*bridge->registry, recipe, why);
}

pfx_vk_status start_gl(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error) {
  if (!bridge->worker) bridge->worker = adapters::GlWorker::start();
  app::ChainRecipe fitted = recipe;
  if (!fit_recipe_to_colour(bridge, &fitted, error))
    return bridge->worker->renderer().empty() ? PFX_VK_NO_GL : PFX_VK_BAD_SETTINGS;
  const pfx_vk_status made = make_gl_chain(bridge, fitted, error);
  if (made != PFX_VK_OK) return made;
  if (bridge->transport) return PFX_VK_OK;
  auto transport = std::make_unique<Transport>(bridge->functions, bridge->device.device, bridge->device.physical_device,
                                               bridge->queue);
  if (!transport->init(bridge->device.queue_family_index, bridge->set_loader_data, error)) return PFX_VK_VULKAN_FAILED;
  bridge->transport = std::move(transport);
  return PFX_VK_OK;
}

pfx_vk_status take_gl_path(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error) {
  const pfx_vk_status started = start_gl(bridge, recipe, error);
  if (started != PFX_VK_OK) return started;
  if (bridge->native) {
    bridge->ring->wait_idle();  // before the instances go
    bridge->native.reset();
  }
  return PFX_VK_OK;
}

pfx_vk_status take_native_path(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error) {
  if (!bridge->ring) {
    auto ring = std::make_unique<CommandRing>(bridge->functions, bridge->device.device, bridge->queue);
    if (!ring->init(bridge->device.queue_family_index, bridge->set_loader_data, error)) return PFX_VK_VULKAN_FAILED;
    bridge->ring = std::move(ring);
  }
  const bool fresh = !bridge->native;
  if (fresh) bridge->native = std::make_unique<NativeChain>();
  CommandRing* ring = bridge->ring.get();
  if (!bridge->native->set_recipe(
          *bridge->registry, recipe, [ring] { ring->wait_idle(); }, error)) {
    if (fresh) bridge->native.reset();
    return PFX_VK_BAD_SETTINGS;
  }
  bridge->chain_text = bridge->native->text();
  // A GL path made for 10-bit frames keeps the same chain.
  std::string gl_error;
  if (bridge->gl && start_gl(bridge, recipe, &gl_error) != PFX_VK_OK)
    bridge->say(1, "10-bit frames keep the chain they had: " + gl_error);
  else if (bridge->gl)
    bridge->chain_text = bridge->native->text();
  return PFX_VK_OK;
}

}  // namespace pfx::vk
