// What a pfx_vk_bridge is (vulkan_bridge.h): the Vulkan device's functions and the transport on
// the caller's side, the plugins and the GL thread with the chain on the other.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include <pfx/host/plugin_registry.hpp>
#include <pfx/vulkan_bridge.h>

#include "gl_frame.hpp"
#include "gl_worker.hpp"
#include "vk_transport.hpp"

struct pfx_vk_bridge {
  pfx_vk_log_fn log = nullptr;
  void* log_user = nullptr;
  pfx::vk::Functions functions;
  std::unique_ptr<pfx::vk::Transport> transport;
  std::unique_ptr<pfx::host::PluginRegistry> registry;
  std::shared_ptr<pfx::adapters::GlWorker> worker;
  std::unique_ptr<pfx::vk::GlFrame> gl;  // made, used and destroyed on the worker
  pfx::app::Transfer transfer = pfx::app::Transfer::SRGB;
  pfx::vk::Path path = pfx::vk::Path::HOST;
  bool dry_run = false;     // PFX_VK_DRY_RUN
  bool ran_passes = false;  // in the last run
  bool submitted = false;   // the last run submitted (pfx_vk_bridge_submitted)
  std::string chain_text;   // GlFrame::chain_text, kept on the caller's side
  // PFX_VK_TIME_PASSES: the newest complete times, copied from the GL thread after each run, and
  // what pfx_vk_bridge_frame_times hands out (pointing into them).
  pfx::host::FrameTimes times;
  std::string timing = "off";
  mutable std::vector<pfx_vk_pass_time> pass_times;
  uint64_t frames = 0;
  std::chrono::steady_clock::time_point first_run;
  std::string last_error;

  void say(int level, const std::string& message) const {
    if (log) log(log_user, level, message.c_str());
  }
};

namespace pfx::vk {

// The steps of pfx_vk_bridge_create, each false with *error.
bool load_bridge_plugins(pfx_vk_bridge* bridge, const char* plugin_path, std::string* error);
// The recipe desc's chain, set and preset give, fitted to a frame of colour alone
// (fit_recipe_to_colour), and the transfer. What does not apply fails it with *error, or with
// PFX_VK_LEAVE_OUT_BAD_SETTINGS is left out and added to *left_out. Needs the plugins and the GL
// thread.
pfx_vk_status settings_recipe(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, app::Transfer* transfer,
                              app::ChainRecipe* recipe, std::vector<app::RecipeProblem>* left_out, std::string* error);
// Each item of the settings left out, and what of the preset did not apply (the recipe's one
// warning), as warnings to the log.
void say_left_out(const pfx_vk_bridge* bridge, const std::vector<app::RecipeProblem>& left_out, const app::ChainRecipe& recipe);
void copy_error(const std::string& message, char* error, size_t error_size);
// Leaves out of the default chain, or switches off in a chosen one, every effect that needs more
// than colour (colour_fit.cpp).
bool fit_recipe_to_colour(pfx_vk_bridge* bridge, app::ChainRecipe* recipe, std::string* error);
// How the chain times its passes for the flags given (PFX_VK_TIME_PASSES), on the GL thread.
host::Timing timing_for(const pfx_vk_bridge* bridge, uint32_t flags);
bool start_bridge_gl(pfx_vk_bridge* bridge, const pfx_vk_bridge_desc& desc, const app::ChainRecipe& recipe,
                     std::string* error);

}  // namespace pfx::vk
