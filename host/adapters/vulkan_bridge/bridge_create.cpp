// pfx_vk_bridge_create and pfx_vk_bridge_destroy: the plugins, the settings and the path the frames
// take (bridge_paths.cpp).
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
  bridge->device.struct_size = sizeof bridge->device;
  bridge->device.instance = desc->instance;
  bridge->device.physical_device = desc->physical_device;
  bridge->device.device = desc->device;
  bridge->device.get_instance_proc_addr = desc->get_instance_proc_addr;
  bridge->device.get_device_proc_addr = desc->get_device_proc_addr;
  bridge->device.queue_family_index = desc->queue_family_index;
  bridge->device.api_version = VK_API_VERSION_1_0;  // what every device offers: the caller does not say
  bridge->queue = desc->queue;
  bridge->set_loader_data = desc->set_device_loader_data;
  bridge->flags = desc->flags;
  std::vector<app::RecipeProblem> left_out;
  const pfx_vk_status settings =
      vk::settings_recipe(bridge.get(), *desc, &bridge->transfer, &bridge->recipe, &left_out, &message);
  if (settings != PFX_VK_OK) {
    vk::copy_error(message, error, error_size);
    pfx_vk_bridge_destroy(bridge.release());
    return settings;
  }
  vk::say_left_out(bridge.get(), left_out, bridge->recipe);
  std::string why;
  const bool native = vk::native_wanted(bridge.get(), desc->flags, bridge->recipe, &why);
  const pfx_vk_status path = native ? vk::take_native_path(bridge.get(), bridge->recipe, &message)
                                    : vk::take_gl_path(bridge.get(), bridge->recipe, &message);
  if (path != PFX_VK_OK) {
    vk::copy_error(message, error, error_size);
    pfx_vk_bridge_destroy(bridge.release());
    return path;
  }
  bridge->say(0, native ? "the chain runs natively on the Vulkan device: no GL, no copies, no waits"
                        : "the chain runs through OpenGL: " + why);
  *out = bridge.release();
  return PFX_VK_OK;
}

extern "C" PFX_VK_API void pfx_vk_bridge_destroy(pfx_vk_bridge* bridge) {
  if (!bridge) return;
  if (bridge->frames)
    bridge->say(0, std::to_string(bridge->frames) + " frames; the CPU waited for the device " +
                       std::to_string(bridge->gl_waits + (bridge->ring ? bridge->ring->waits() : 0)) +
                       " times (read-backs for captures aside)");
  if (bridge->ring) bridge->ring->wait_idle();  // the native instances' work first
  bridge->native.reset();
  bridge->readback.reset();
  bridge->ring.reset();
  bridge->transport.reset();  // waits for its copies first
  if (bridge->worker) {
    std::string ignored;
    bridge->worker->run([bridge] { bridge->gl.reset(); }, &ignored);
  }
  bridge->worker.reset();
  bridge->registry.reset();  // after the effects made from it
  delete bridge;
}
