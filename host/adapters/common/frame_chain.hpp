// The chain an adapter runs over one 8-bit frame: effect instances and their values (starting at
// the display-referred defaults, since such a frame holds nothing above 1.0), run from the
// decoded frame to the texture that is encoded back. Made, used and destroyed on the thread where
// the adapter's GL context is current.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "chain_builder.hpp"
#include "display_frame.hpp"

namespace pfx::adapters {

class FrameChain {
 public:
  // Creates the effects (their programs compile now). Null with *error naming the effect or the
  // assignment (which starts with set_origin, the setting that gave it); *notes gets values the
  // store adjusted (clamped to their range).
  static std::unique_ptr<FrameChain> build(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                                           const std::string& set_origin, std::vector<std::string>* notes,
                                           std::string* error);
  ~FrameChain();

  // Takes a new recipe while frames run (a preset edited in a panel): when it names the same
  // effects in the same order only the values and on/off flags change and no effect is created
  // again; otherwise the effects are made anew. All or nothing: false with *error and the chain
  // as it was.
  bool update(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, const std::string& set_origin,
              std::vector<std::string>* notes, std::string* error);
  // "bloom,glare (off)": the chain's instances, those switched off marked; "none" for no effect.
  std::string text() const;

  host::ParamStore& params() { return *params_; }
  host::Chain& chain() { return *chain_; }
  // Whether any effect is on: without one the decoded frame goes straight back out.
  bool runs_effects() const;

  // Whether a frame of that size and time would run any pass: false with no effect on, or when
  // every effect on is a no-op with its values. Then the adapter hands its frame on as it came,
  // with no decode, chain or encode (the round trip gives every 8-bit code back anyway). False
  // with *error when an effect's declare fails.
  bool plans_passes(int width, int height, double time_seconds, uint64_t frame_index, bool* passes,
                    std::string* error) const;

  // Runs the chain over frame.color() into frame.output(); *result is the texture to encode
  // (frame.color() when no effect is on). False with *error naming the effect or pass.
  bool render(gl::DisplayFrame& frame, double time_seconds, uint64_t frame_index, GLuint* result, std::string* error);
  // The same over a frame already in two 8-bit textures of the host's (width x height, bottom row
  // first, each as the transfer reads it: host::FrameTextures): the chain reads `color` and writes
  // `output`, or with no effect on the frame's bits are copied across.
  bool render(GLuint color, GLuint output, int width, int height, double time_seconds, uint64_t frame_index,
              std::string* error);

 private:
  FrameChain() = default;
  std::unique_ptr<host::ParamStore> params_;
  std::unique_ptr<host::Chain> chain_;
};

// What an adapter tells its effects about a frame of that size: colour alone (no depth, normals or
// lights arrive with a video frame or an application's), at the time and frame index the host
// gives (a non-finite time is none).
pfx_frame describe_video_frame(int width, int height, double time_seconds, uint64_t frame_index);

// After a frame: false with *error ("GL error 0x0505 while running the chain") when the GL
// reports an error.
bool no_gl_error(std::string* error);

}  // namespace pfx::adapters
