// pfx_vk_bridge_update: new settings for a running bridge (a preset edited while the application
// runs), read as pfx_vk_bridge_create reads them.
#include "bridge.hpp"

using namespace pfx;

extern "C" PFX_VK_API pfx_vk_status pfx_vk_bridge_update(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc* desc,
                                                         char* error, size_t error_size) {
  if (!bridge || !desc || desc->struct_size < sizeof(pfx_vk_bridge_desc)) {
    vk::copy_error("pfx_vk_bridge_update: a null argument or a struct_size too small", error, error_size);
    return PFX_VK_BAD_ARGUMENT;
  }
  app::Transfer transfer = bridge->transfer;
  app::ChainRecipe recipe;
  std::vector<app::RecipeProblem> left_out;
  std::string message;
  pfx_vk_status status = vk::settings_recipe(bridge, *desc, &transfer, &recipe, &left_out, &message);
  // A preset that does not read or apply is refused whole, even where other settings may be left
  // out: the chain that runs stays (pfx-inject's rule for a changed preset).
  for (const auto& problem : left_out)
    if (status == PFX_VK_OK && problem.source == app::RecipeProblem::PRESET) {
      status = PFX_VK_BAD_SETTINGS;
      message = "preset: " + problem.message;
    }
  // The path the new chain takes, said when it is not the one the old chain took.
  std::string why;
  const bool native = status == PFX_VK_OK && vk::native_wanted(bridge, desc->flags, recipe, &why);
  const bool was_native = bridge->native != nullptr;
  if (status == PFX_VK_OK) {
    const uint32_t old_flags = bridge->flags;
    bridge->flags = (desc->flags & ~PFX_VK_FORCE_HOST_MEMORY) | (old_flags & PFX_VK_FORCE_HOST_MEMORY);
    status = native ? vk::take_native_path(bridge, recipe, &message) : vk::take_gl_path(bridge, recipe, &message);
    if (status != PFX_VK_OK) bridge->flags = old_flags;
  }
  if (status != PFX_VK_OK) {
    vk::copy_error(message, error, error_size);
    return status;
  }
  vk::say_left_out(bridge, left_out, recipe);
  bridge->transfer = transfer;
  bridge->recipe = recipe;
  bridge->dry_run = (desc->flags & PFX_VK_DRY_RUN) != 0;
  if (native != was_native)
    bridge->say(0, native ? "the chain runs natively on the Vulkan device from now on"
                          : "the chain runs through OpenGL from now on: " + why);
  bridge->say(0, "settings applied: chain " + bridge->chain_text);
  return PFX_VK_OK;
}
