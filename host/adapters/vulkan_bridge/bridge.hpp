// What a pfx_vk_bridge is (vulkan_bridge.h): the Vulkan device's functions and the transport on
// the caller's side, the plugins and the GL thread with the chain on the other.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include <pfx/host/plugin_registry.hpp>
#include <pfx/vulkan_bridge.h>

#include "command_ring.hpp"
#include "frame_readback.hpp"
#include "gl_frame.hpp"
#include "gl_worker.hpp"
#include "native_chain.hpp"
#include "vk_transport.hpp"

struct pfx_vk_bridge {
  pfx_vk_log_fn log = nullptr;
  void* log_user = nullptr;
  pfx::vk::Functions functions;
  // The caller's device and queue, and the desc's flags: what either path is made from.
  pfx_vk_device device{};
  VkQueue queue = VK_NULL_HANDLE;
  pfx::vk::SetLoaderData set_loader_data = nullptr;
  uint32_t flags = 0;
  std::unique_ptr<pfx::host::PluginRegistry> registry;
  // The chain as the settings give it, before the GL path fits it to colour: what a GL path
  // started later (a 10-bit frame on a native bridge) starts from.
  pfx::app::ChainRecipe recipe;
  // The native path (native_chain.hpp), set while every effect of the chain runs on Vulkan; its
  // command buffers; the read-backs of the frames that ask for them (made at the first).
  std::unique_ptr<pfx::vk::NativeChain> native;
  std::unique_ptr<pfx::vk::CommandRing> ring;
  std::unique_ptr<pfx::vk::FrameReadback> readback;
  // The GL path, each made when it is first taken: the transport, the GL thread and the chain.
  std::unique_ptr<pfx::vk::Transport> transport;
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
  // Waits of the CPU for the device in the runs, for the log at the end: on the GL path two a frame
  // the chain ran on (the copy in, the GL's finish); on the native path those CommandRing::waits
  // counts (read-backs, which wait by design, aside).
  uint64_t gl_waits = 0;
  std::chrono::steady_clock::time_point first_run;
  std::string last_error;

  void say(int level, const std::string& message) const {
    if (log) log(log_user, level, message.c_str());
  }
};

namespace pfx::vk {

// The steps of pfx_vk_bridge_create, each false with *error.
bool load_bridge_plugins(pfx_vk_bridge* bridge, const char* plugin_path, std::string* error);
// The recipe desc's chain, set and preset give, and the transfer. What does not apply fails it with
// *error, or with PFX_VK_LEAVE_OUT_BAD_SETTINGS is left out and added to *left_out. Needs the
// plugins.
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
// Whether the recipe runs on the native path with these flags (bridge_paths.cpp); else false with
// *why, for the log.
bool native_wanted(const pfx_vk_bridge* bridge, uint32_t flags, const app::ChainRecipe& recipe, std::string* why);
// Takes the native path with the recipe (making its command buffers the first time); false with
// *error and the status to return.
pfx_vk_status take_native_path(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error);
// Starts the GL path with the recipe, leaving a native path as it is (for 10-bit frames, which
// only the GL path takes): starts the GL thread, fits the recipe to colour, makes the
// chain (or hands it the recipe when it is made) and the transport, as far as they are not made
// yet. False with *error and the status to return.
pfx_vk_status start_gl(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error);
// start_gl, then the native path (if any) goes.
pfx_vk_status take_gl_path(pfx_vk_bridge* bridge, const app::ChainRecipe& recipe, std::string* error);

}  // namespace pfx::vk
