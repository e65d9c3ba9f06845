// The GL half of a frame's trip through the bridge, on the bridge's GL thread: the frame (in
// memory shared with Vulkan, or uploaded from host memory) brought into the chain's textures by
// DisplayFrame, the chain, the result handed back into the same place. Images arrive top row first,
// as Vulkan stores them, and DisplayFrame flips them into GL's bottom-row-first order and back;
// a go-between that Vulkan's blits filled (vk_transport.hpp) is the chain's textures already.
#pragma once

#include <memory>
#include <string>

#include <pfx/host/plugin_registry.hpp>

#include "display_frame.hpp"
#include "frame_chain.hpp"
#include "gl_memory.hpp"

namespace pfx::vk {

class GlFrame {
 public:
  // Compiles the transfer programs and creates the effects; false with *error.
  bool create(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, std::string* error);
  ~GlFrame();

  // A new recipe while frames run (FrameChain::update): false with *error and the chain as it was.
  bool update(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, std::string* error) {
    std::vector<std::string> notes;
    if (!chain_->update(registry, recipe, "set", &notes, error)) return false;
    chain_->chain().set_timing(timing_);
    return true;
  }
  std::string chain_text() const { return chain_->text(); }
  // How passes are timed (host::Chain::set_timing), kept when update() makes the effects anew.
  void set_timing(host::Timing timing) {
    timing_ = timing;
    chain_->chain().set_timing(timing);
  }
  const host::FrameReport& report() const { return chain_->chain().report(); }

  GlMemory& shared() { return shared_; }
  // Whether a frame of that size and time would run any pass (FrameChain::plans_passes). False
  // with *error when an effect's declare fails.
  bool plans_passes(int width, int height, double time_seconds, uint64_t frame_index, bool* passes,
                    std::string* error) const {
    return chain_->plans_passes(width, height, time_seconds, frame_index, passes, error);
  }
  // What the frame's 32-bit texels hold: 8-bit R, G, B, A in that order of bytes, or 10-bit
  // R, G, B and 2-bit alpha from the lowest bits up (ten_bit); bgra: blue and red trade places.
  struct Texels {
    bool bgra = false;
    bool ten_bit = false;
  };
  // Runs the chain over the frame: from host_bytes (tightly packed rows of texels, top row first,
  // read and written back) when not null, else in the shared texture. app_pixels and
  // result_pixels, when not null, receive the frame before and after as 8-bit RGBA (pfx_vk_image
  // says how). Returns after the GL finished. False with *error.
  struct Readback {
    uint8_t* app_pixels = nullptr;
    uint8_t* result_pixels = nullptr;
  };
  bool run(void* host_bytes, int width, int height, Texels texels, app::Transfer transfer, double time_seconds,
           uint64_t frame_index, const Readback& readback, std::string* error);
  // The same over a go-between of two layers (GlMemory::layer): the chain samples layer 0 and draws
  // layer 1, which the blits have already turned over and put in R, G, B, A order.
  bool run_on_layers(int width, int height, app::Transfer transfer, double time_seconds, uint64_t frame_index,
                     const Readback& readback, std::string* error);

 private:
  GLuint staging(int width, int height, bool ten_bit);
  gl::DisplayFrame frame_;
  std::unique_ptr<adapters::FrameChain> chain_;
  GlMemory shared_;
  host::Timing timing_ = host::Timing::OFF;
  GLuint staging_ = 0;
  int staging_width_ = 0, staging_height_ = 0;
  bool staging_ten_bit_ = false;
};

}  // namespace pfx::vk
