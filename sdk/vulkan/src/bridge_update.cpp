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
  std::string chain;
  if (status == PFX_VK_OK) {
    bool updated = false;
    if (!bridge->worker->run(
            [&] {
              updated = bridge->gl->update(*bridge->registry, recipe, &message);
              if (!updated) return;
              chain = bridge->gl->chain_text();
              bridge->gl->set_timing(vk::timing_for(bridge, desc->flags));
            },
            &message) ||
        !updated)
      status = PFX_VK_CHAIN_FAILED;
  }
  if (status != PFX_VK_OK) {
    vk::copy_error(message, error, error_size);
    return status;
  }
  vk::say_left_out(bridge, left_out, recipe);
  bridge->transfer = transfer;
  bridge->chain_text = chain;
  bridge->dry_run = (desc->flags & PFX_VK_DRY_RUN) != 0;
  bridge->say(0, "settings applied: chain " + chain);
  return PFX_VK_OK;
}
