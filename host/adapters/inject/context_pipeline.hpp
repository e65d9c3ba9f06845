// The chain in one of the application's GL contexts: its effect instances and parameter values,
// the copy in and out, and what one present does. Made, used and destroyed on the thread where
// that context is current.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "chain_recipe.hpp"
#include "depth_check.hpp"
#include "frame_copy.hpp"
#include "input_fit.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

// What one present asks of the pipeline.
struct FrameWork {
  int width = 0, height = 0;          // the surface's size
  uint64_t frame = 0;                 // which presented frame, from 1
  double time_seconds = 0;            // since the first present
  std::vector<std::string> captures;  // prefixes to write this frame
  bool measure_copy_pass = false;     // time the copy-pass unit this frame (bench)
};

class ContextPipeline {
 public:
  // Checks the current context (desktop OpenGL 4.5 or later, double-buffered) and builds the
  // chain. Null with *reason, one line for the log, when this context cannot run it.
  static std::unique_ptr<ContextPipeline> create(const host::PluginRegistry& registry, const InjectSettings& settings,
                                                 const ChainRecipe& recipe, std::vector<std::string>* notes,
                                                 std::string* reason);
  ~ContextPipeline();

  // Replaces the chain and its values (a changed preset). *notes gets the effects a default chain
  // leaves out. False with *reason, keeping the old.
  bool rebuild(const ChainRecipe& recipe, std::vector<std::string>* notes, std::string* reason);
  // Runs the chain over the back buffer and, unless a dry run, encodes the result into it. Every
  // piece of GL state it touches is put back. False with *reason when it failed: the caller then
  // leaves this context's frames alone.
  bool process(const FrameWork& work, std::vector<std::string>* messages, std::string* reason);
  // Whether the last process() ran passes (false: the frame was left as the application drew it).
  bool ran_passes() const { return ran_passes_; }
  // The copy-pass unit measured on the last frame that asked (0 before).
  double copy_pass_ms() const { return copy_pass_ms_; }
  std::string chain_text() const;
  // The chain's report of its last frame (times there when the settings ask for a timings file).
  const host::FrameReport& report() const { return chain_->report(); }

 private:
  ContextPipeline(const host::PluginRegistry& registry, const InjectSettings& settings);
  // The frame the chain gets at that size with those inputs: the camera from the depth planes.
  pfx_frame frame_for(int width, int height, uint32_t inputs) const;
  // Whether the user switched any effect on (InputFit may have switched some off for now).
  bool wanted_any() const;
  // *nothing: no effect is on, or every one on is a no-op with its values whatever the depth
  // holds, so the frame needs nothing copied. False with *reason when declare fails.
  bool nothing_to_run(const FrameWork& work, bool* nothing, std::string* reason) const;
  // Copies and checks the back buffer's depth and fits the chain to what it holds: the inputs the
  // frame has. *ok false with *reason when fitting failed.
  uint32_t fit_to_depth(const FrameWork& work, std::vector<std::string>* messages, std::string* reason, bool* ok);
  // Whether `recipe` names the effects the chain was built from, in the same order.
  bool same_effects(const ChainRecipe& recipe) const;
  // Puts the recipe's values and on/off flags into the chain that runs; false with *reason.
  bool update_values(const ChainRecipe& recipe, std::vector<std::string>* notes, std::string* reason);
  const host::PluginRegistry& registry_;
  const InjectSettings& settings_;
  std::unique_ptr<host::ParamStore> params_;
  std::unique_ptr<host::Chain> chain_;
  InputFit fit_;
  ChainRecipe built_;  // what the chain was built or last updated from
  FrameCopy copy_;
  DepthCheck depth_check_;
  bool depth_said_ = false;
  bool output_said_ = false;  // where the chain's result goes was logged
  std::string renderer_;  // GL_RENDERER, to choose how passes are timed
  double copy_pass_ms_ = 0;
  bool ran_passes_ = false;
};

}  // namespace pfx::inject
