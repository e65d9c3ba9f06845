// pfx_vk_bridge_create and pfx_vk_bridge_destroy: the plugins, the settings, the GL thread and the
// path the frames take.
#include <cstdlib>
#include <cstring>

#include "adapter_plugins.hpp"
#include "bridge.hpp"
#include "chain_settings.hpp"
#include "cli_text.hpp"
#include "headless_context.hpp"
#include "timing_choice.hpp"

namespace pfx::vk {
namespace {

const char* const kDeviceExtensions[] = {"VK_KHR_external_memory", "VK_KHR_external_memory_fd"};

bool forced_host_memory(const pfx_vk_bridge_desc& desc) {
  const char* variable = std::getenv("PFX_VK_HOST_MEMORY");
  return (desc.flags & PFX_VK_FORCE_HOST_MEMORY) || (variable && std::strcmp(variable, "1") == 0);
}

// Whether GL and Vulkan can share memory, and why not: the GL side is asked on the worker.
Path choose_path(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, std::string* why) {
  if (forced_host_memory(desc)) {
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
  bridge->functions.GetPhysicalDeviceProperties2(desc.physical_device, &properties);
  bool shares = false;
  std::string worker_error;
  if (!bridge->worker->run([&] { shares = bridge->gl->shared().check(ids.deviceUUID, ids.driverUUID, why); },
                           &worker_error))
    *why = worker_error;
  return shares ? Path::SHARED : Path::HOST;
}

bool leaves_out_bad_settings(const pfx_vk_bridge_desc& desc) { return (desc.flags & PFX_VK_LEAVE_OUT_BAD_SETTINGS) != 0; }

// Without a chain given: the preset's, else every effect found in pfx's order. What does not apply
// is an error, or goes to *left_out when that is given.
bool default_chain_recipe(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, app::ChainRecipe* recipe,
                          std::vector<app::RecipeProblem>* left_out, std::string* error) {
  std::vector<app::RecipeProblem> problems;
  std::vector<std::string> notes;
  const std::vector<std::string> sets = adapters::split_assignments(desc.set ? desc.set : "");
  *recipe = app::make_chain_recipe(desc.preset ? desc.preset : "", std::nullopt, sets, *bridge->registry,
                                   app::WithoutChain::DEFAULT_CHAIN, &problems, &notes);
  if (problems.empty()) return true;
  if (left_out) {
    left_out->insert(left_out->end(), problems.begin(), problems.end());
    return true;
  }
  *error = problems.front().message;
  return false;
}

}  // namespace

void copy_error(const std::string& message, char* error, size_t error_size) {
  if (!error || !error_size) return;
  std::strncpy(error, message.c_str(), error_size - 1);
  error[error_size - 1] = '\0';
}

void say_left_out(const pfx_vk_bridge* bridge, const std::vector<app::RecipeProblem>& left_out, const app::ChainRecipe& recipe) {
  for (const auto& item : adapters::describe_problems(left_out)) bridge->say(1, "ignored " + item);
  if (!recipe.left_out.empty()) bridge->say(1, recipe.left_out);
}

pfx_vk_status settings_recipe(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, app::Transfer* transfer,
                              app::ChainRecipe* recipe, std::vector<app::RecipeProblem>* left_out, std::string* error) {
  const adapters::ChainSettings settings{desc.chain ? desc.chain : "", desc.set ? desc.set : "",
                                         desc.transfer ? desc.transfer : "", desc.preset ? desc.preset : ""};
  const bool lenient = leaves_out_bad_settings(desc);
  // With no chain given the default chain's recipe reads the preset and the assignments again:
  // what they lack is said once, from there.
  std::vector<app::RecipeProblem> problems;
  if (!adapters::resolve_chain_settings(settings, *bridge->registry, transfer, recipe, error, lenient ? &problems : nullptr))
    return PFX_VK_BAD_SETTINGS;
  if (desc.chain) left_out->insert(left_out->end(), problems.begin(), problems.end());
  else if (!default_chain_recipe(bridge, desc, recipe, lenient ? left_out : nullptr, error))
    return PFX_VK_BAD_SETTINGS;
  if (!fit_recipe_to_colour(bridge, recipe, error))
    return bridge->worker->renderer().empty() ? PFX_VK_NO_GL : PFX_VK_BAD_SETTINGS;
  return PFX_VK_OK;
}

bool load_bridge_plugins(pfx_vk_bridge* bridge, const char* plugin_path, std::string* error) {
  bridge->registry = std::make_unique<host::PluginRegistry>(
      [](const char* name) { return app::HeadlessContext::get_proc_address(nullptr, name); },
      [bridge](pfx_log_level level, const std::string& source, const std::string& message) {
        if (level >= PFX_LOG_WARNING) bridge->say(level == PFX_LOG_WARNING ? 1 : 2, "[" + source + "] " + message);
      },
      "pfx Vulkan bridge");
  std::vector<std::string> messages;
  if (plugin_path && *plugin_path) {
    messages = bridge->registry->load_search_path(app::split_list(plugin_path, ':'));
    for (const auto& message : bridge->registry->source_errors()) messages.push_back("no effect from " + message);
  } else {
    const adapters::PluginFolderRule rule{
        adapters::library_path_of(reinterpret_cast<const void*>(&pfx_vk_bridge_create)),
        {"../plugins", "pfx/plugins", "../pfx/plugins"}};
    messages = adapters::load_adapter_plugins(*bridge->registry, rule);
  }
  for (const auto& message : messages) bridge->say(1, message);
  if (bridge->registry->effects().empty()) {
    *error = "no pfx effect plugins found" + (messages.empty() ? "" : ": " + messages.front());
    return false;
  }
  return true;
}

host::Timing timing_for(const pfx_vk_bridge* bridge, uint32_t flags) {
  return flags & PFX_VK_TIME_PASSES ? app::default_timing(bridge->worker->renderer()) : host::Timing::OFF;
}

bool start_bridge_gl(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, const app::ChainRecipe& recipe,
                     std::string* error) {
  bool created = false;
  if (!bridge->worker->run(
          [&] {
            bridge->gl = std::make_unique<GlFrame>();
            created = bridge->gl->create(*bridge->registry, recipe, error);
            if (!created) return;
            bridge->chain_text = bridge->gl->chain_text();
            bridge->gl->set_timing(timing_for(bridge, desc.flags));
          },
          error))
    return false;
  if (!created) return false;
  std::string why;
  bridge->path = choose_path(bridge, desc, &why);
  bridge->say(0, bridge->path == Path::SHARED ? "frames go through memory shared with the GL (" +
                                                    bridge->worker->renderer() + ")"
                                              : "frames go through host memory: " + why);
  return true;
}

}  // namespace pfx::vk

using namespace pfx;

extern "C" PFX_VK_API const char* const* pfx_vk_bridge_device_extensions(uint32_t* count) {
  if (count) *count = 2;
  return vk::kDeviceExtensions;
}

extern "C" PFX_VK_API pfx_vk_status pfx_vk_bridge_create(const pfx_vk_bridge_desc* desc, pfx_vk_bridge** out,
                                                         char* error, size_t error_size) {
  if (out) *out = nullptr;
  if (!desc || !out || desc->struct_size < sizeof(pfx_vk_bridge_desc) || !desc->device || !desc->queue ||
      !desc->physical_device || !desc->get_instance_proc_addr || !desc->get_device_proc_addr) {
    vk::copy_error("pfx_vk_bridge_create: a null argument or a struct_size too small", error, error_size);
    return PFX_VK_BAD_ARGUMENT;
  }
  auto bridge = std::make_unique<pfx_vk_bridge>();
  bridge->log = desc->log;
  bridge->log_user = desc->log_user;
  bridge->dry_run = (desc->flags & PFX_VK_DRY_RUN) != 0;
  std::string message;
  const bool want_fd = desc->device_has_bridge_extensions != 0;
  if (!vk::load_functions(desc->instance, desc->device, desc->get_instance_proc_addr, desc->get_device_proc_addr,
                          want_fd, &bridge->functions, &message)) {
    vk::copy_error(message, error, error_size);
    return PFX_VK_VULKAN_FAILED;
  }
  if (!vk::load_bridge_plugins(bridge.get(), desc->plugin_path, &message)) {
    vk::copy_error(message, error, error_size);
    return PFX_VK_BAD_SETTINGS;
  }
  bridge->worker = adapters::GlWorker::start();
  app::ChainRecipe recipe;
  std::vector<app::RecipeProblem> left_out;
  const pfx_vk_status settings = vk::settings_recipe(bridge.get(), *desc, &bridge->transfer, &recipe, &left_out, &message);
  if (settings != PFX_VK_OK) {
    vk::copy_error(message, error, error_size);
    pfx_vk_bridge_destroy(bridge.release());
    return settings;
  }
  vk::say_left_out(bridge.get(), left_out, recipe);
  if (!vk::start_bridge_gl(bridge.get(), *desc, recipe, &message)) {
    vk::copy_error(message, error, error_size);
    // A worker that made its context ran the chain's creation: then an effect failed.
    const bool has_gl = bridge->worker && !bridge->worker->renderer().empty();
    pfx_vk_bridge_destroy(bridge.release());
    return has_gl ? PFX_VK_CHAIN_FAILED : PFX_VK_NO_GL;
  }
  bridge->transport = std::make_unique<vk::Transport>(bridge->functions, desc->device, desc->physical_device,
                                                      desc->queue);
  if (!bridge->transport->init(desc->queue_family_index, desc->set_device_loader_data, &message)) {
    vk::copy_error(message, error, error_size);
    pfx_vk_bridge_destroy(bridge.release());
    return PFX_VK_VULKAN_FAILED;
  }
  *out = bridge.release();
  return PFX_VK_OK;
}

extern "C" PFX_VK_API void pfx_vk_bridge_destroy(pfx_vk_bridge* bridge) {
  if (!bridge) return;
  bridge->transport.reset();  // waits for its copies first
  if (bridge->worker) {
    std::string ignored;
    bridge->worker->run([bridge] { bridge->gl.reset(); }, &ignored);
  }
  bridge->worker.reset();
  bridge->registry.reset();  // after the effects made from it
  delete bridge;
}
