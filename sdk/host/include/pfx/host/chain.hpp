// The chain: an ordered list of effect instances run over the host's framebuffers
// (docs/architecture.md: the frame's path from declare to plan to execute). Every call on the GL
// thread with the context current.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pfx/pfx.h>

#include "pfx/host/api.hpp"
#include "pfx/host/frame_plan.hpp"
#include "pfx/host/param_store.hpp"
#include "pfx/host/plugin_registry.hpp"
#include "pfx/host/timing.hpp"

namespace pfx::host {

// libpfxhost's own types, behind the chain's private members.
struct GlLimits;        // what GlStateGuard saves per indexed binding
class FrameTimer;       // times a frame's passes under the chosen Timing
struct FrameResources;  // the textures one render() runs over
struct HostOutput;      // the texture or framebuffer one render() writes

// GL textures of the frame inputs; 0 where the frame has none (frame.inputs must agree).
// color and the chain's output are textures of the frame's size: RGBA16F holding linear light (what
// the ABI promises every effect), or, for a host of 8-bit display frames, 8-bit: GL_SRGB8_ALPHA8
// (a view of the frame's texture) holding sRGB-encoded values, or GL_RGBA8 holding linear ones. An
// effect that promised PFX_DECLARATION_SAMPLES_AND_DRAWS then reads and writes those as they are,
// with no pass to convert them; for the others the chain converts on that side (one draw each).
struct FrameTextures {
  uint32_t color = 0, depth = 0, normal = 0, albedo = 0, emissive = 0;
};

// The chain's result drawn into a framebuffer of the host's instead of a texture, for a host whose
// destination is not one: pfx-inject draws into the application's back buffer (framebuffer 0).
// Its draw buffer is 8-bit, of the frame's size, and selected by the host; it holds sRGB codes
// (`srgb`: the chain draws with GL_FRAMEBUFFER_SRGB, so the buffer must be sRGB-capable,
// GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING GL_SRGB) or linear ones. The last effect's passes draw
// straight into it when that effect promised PFX_DECLARATION_SAMPLES_AND_DRAWS and never reads its
// own "output" back (a framebuffer cannot be sampled); otherwise it writes the chain's RGBA16F
// texture, drawn into the framebuffer after (one pass of "chain").
struct FramebufferOutput {
  uint32_t framebuffer = 0;
  bool srgb = true;
};

struct FrameReport {
  uint64_t frame = 0;                        // which render() this is: 1 for the chain's first
  std::vector<std::string> effects_run;      // enabled effects that declared passes, in order
  std::vector<std::string> effects_skipped;  // disabled, or no-op with their settings
  // Every pass that ran this frame, in order. ms is this frame's time where it is known when
  // render() returns (FINISH_AND_CLOCK) or after wait_for_timings(); 0 otherwise.
  std::vector<PassTime> passes;
  // The newest frame whose times are complete: this frame with FINISH_AND_CLOCK, an earlier one
  // (or none: frame 0) with GPU_QUERIES until wait_for_timings(), none with OFF.
  FrameTimes times;
  std::string timing;                        // "gpu-timestamps", "finish+clock" or "off"
  uint64_t peak_target_bytes = 0;            // pooled targets alive during the frame
  uint64_t unpooled_target_bytes = 0;        // what they would cost without pooling
  // Per effect that reports figures: its id and the JSON members it returned.
  std::vector<std::pair<std::string, std::string>> effect_reports;
};

class PFX_HOST_API Chain {
 public:
  // The chain's instances read their values from `params` (ParamStore says how the store follows
  // the chain), which must outlive the chain.
  Chain(const PluginRegistry& registry, ParamStore& params);
  // Destroys every instance and pooled GL object: the context must be current. The values stay in
  // the store.
  ~Chain();
  Chain(const Chain&) = delete;
  Chain& operator=(const Chain&) = delete;

  // Appends an instance of an effect (created now, so its programs compile now) and registers its
  // parameters in the store if they are not there yet. The N-th instance of an effect in the
  // chain uses the store's values of "effect#N" (at the defaults when the store had no such
  // instance). False with *error on an unknown id, a failing create or a plugin that refuses the
  // chain's source definitions (set_source_definitions).
  bool add(const std::string& effect_id, std::string* error);
  size_t size() const;
  std::string effect_id(size_t index) const;
  // Which instance of its effect the one at `index` is, counting from 1 in chain order (disabled
  // ones count), and its name in the store: "bloom" for the first, "bloom#2" for the second.
  size_t instance_number(size_t index) const;
  std::string instance_name(size_t index) const;
  void set_enabled(size_t index, bool enabled);
  bool enabled(size_t index) const;
  // Removes the instance and its values from the store (the others of its effect renumber), but
  // an effect's last instance leaves its values in the store, so a chain rebuilt from scratch
  // finds them again.
  void remove(size_t index);
  // Values travel with the instance: the store's blocks are reordered with it.
  void move(size_t from, size_t to);

  // After PluginRegistry::reload (use reload_plugin() in hot_reload.hpp, which also moves the
  // parameters over): re-creates every instance whose effect now comes from another library
  // version, keeping its place and enabled flag, and removes those whose effect is gone (their ids
  // are appended to *dropped). All or nothing: the new instances are created first, and when one
  // fails the old ones stay and *error names the effect. The old version must still be loaded.
  bool refresh(std::vector<std::string>* dropped, std::string* error);

  // Preprocessor definitions for every instance of an effect made from a source file whose plugin
  // takes them (pfx/sources.h's set_definitions: the FX plugin), "NAME=VALUE,FLAG" as a ReShade
  // preset's PreprocessorDefinitions= line gives them, "" for none; chain-wide, as a preset's are.
  // Instances added later and those refresh() re-creates get them too; each compiles with them
  // before its next frame. False with *error naming the effect whose plugin refused them (a
  // malformed list): the chain then keeps, and puts back, the definitions it had.
  bool set_source_definitions(const std::string& definitions, std::string* error);
  const std::string& source_definitions() const { return source_definitions_; }

  // The PFX_INPUT_* bits the instance at `index` needs with its current values over a frame like
  // `frame` (give it the inputs the host has: an effect may adapt to them): what its declaration
  // names, beside the textures its passes read (a declaration without passes may still name
  // inputs). Enabled or not. For a host that cannot give every input (pfx-inject has no normals
  // or lights) to leave out the effects that need them instead of failing the frame. False with
  // *error when declare fails.
  bool inputs_needed(size_t index, const pfx_frame& frame, uint32_t* inputs, std::string* error) const;

  // Whether render() over `frame` would run any pass: every enabled instance declares with its
  // current values (cheap by contract) and nothing runs. *passes is false when no effect is
  // enabled or every enabled one would be skipped as a no-op. For a host that converts its frame
  // before the chain and back after (an 8-bit frame decoded to RGBA16F): asked first, a "no" lets
  // it hand the frame on untouched instead of converting it both ways around a copy. False with
  // *error when declare fails.
  bool plans_passes(const pfx_frame& frame, bool* passes, std::string* error) const;

  // Changing the scheme drops the times of frames still in flight.
  void set_timing(Timing timing);
  Timing timing() const { return timing_; }
  // Waits for the GPU to finish the last render() that ran passes and puts its times in
  // report().times (and report().passes when it was this report's frame). With GPU_QUERIES
  // this blocks (GL_QUERY_RESULT): for a program that renders one frame and exits, or a
  // benchmark; render() itself never waits. True when report().times now holds the last frame
  // that ran passes; false with timing OFF or before any frame ran a pass.
  bool wait_for_timings();

  // Called around every plugin pass: with after == false once the host has set the pass's GL
  // state (docs/sdk.md §1.5), just before run_pass; with after == true as soon as run_pass
  // returns, before the host touches GL again. For tools that watch what plugins do (pfx-validate
  // compares GL state across the call); costs nothing when unset.
  using PassHook = std::function<void(const std::string& effect, const std::string& pass, bool after)>;
  void set_pass_hook(PassHook hook) { pass_hook_ = std::move(hook); }

  // Runs the enabled effects over the frame: reads textures (as frame.inputs says), writes
  // output_texture. Effects that declare no passes are skipped at no cost; with none left the
  // colour is copied. False with *error naming the effect, pass or input on failure.
  bool render(const pfx_frame& frame, const FrameTextures& textures, uint32_t output_texture, std::string* error);
  // The same, drawing the result into the host's framebuffer (FramebufferOutput says when the
  // effects draw there themselves). With no pass to run the colour is blitted or drawn into it.
  bool render(const pfx_frame& frame, const FrameTextures& textures, const FramebufferOutput& output,
              std::string* error);

  const FrameReport& report() const { return report_; }
  const FramePlan& plan() const { return plan_; }

 private:
  friend class GlStateGuard;  // saves state with the limits the chain queried, and counts itself
  struct Instance;
  struct GlResources;
  // The implementation limits queried when the chain was made; null without GL.
  const GlLimits* gl_limits() const;
  void renumber();
  // Hands the chain's source definitions to a fresh instance of `info` (nothing for an effect of
  // another kind); false with *error when its plugin refuses them.
  bool define_sources(const EffectInfo& info, void* handle, const std::string& definitions, std::string* error) const;

  // A frame, step by step: check the call, declare (every frame: declare is cheap by contract),
  // plan (only when a declaration or the active set changed), execute the plan's passes.
  bool render_into(const pfx_frame& frame, const FrameTextures& textures, const HostOutput& output,
                   std::string* error);
  bool check_frame(const pfx_frame& frame, const FrameTextures& textures, const HostOutput& output,
                   std::string* error) const;
  bool declare(const Instance& instance, const pfx_frame& frame, Declaration* out, std::string* error) const;
  bool declare_all(const pfx_frame& frame, std::vector<int>* active, std::string* error);
  bool update_plan(const pfx_frame& frame, const std::vector<int>& active, std::string* error);
  bool execute(FrameResources& resources, const std::vector<int>& active, std::string* error);
  // The frame's passes in order: the chain's steps at either end (frame_ends), the effects' passes
  // and the conversions the plan put between effects, each timed and reported.
  bool run_frame(FrameResources& resources, const std::vector<int>& active, FrameTimer& timer, std::string* error);
  bool run_conversion(const FrameResources& resources, const PlannedPass& planned, std::string* error);
  void chain_pass(FrameTimer& timer, const std::string& name);
  // One planned pass: bind its output and inputs, run it (timed), check what it left.
  bool run_pass(const FrameResources& resources, const PlannedPass& planned, Instance& instance,
                FrameTimer& timer, std::string* error);
  void collect_effect_reports(const std::vector<int>& active);

  const PluginRegistry& registry_;
  ParamStore& params_;
  std::vector<std::unique_ptr<Instance>> instances_;
  std::unique_ptr<GlResources> gl_;
  FramePlan plan_;
  std::vector<int> planned_active_;  // the instances plan_ was made for
  bool plan_valid_ = false;
  bool gl_loaded_ = false;
  Timing timing_ = Timing::OFF;
  uint64_t frames_ = 0;             // render() calls so far
  uint64_t last_timed_frame_ = 0;   // the last frame that ran passes under a timing scheme
  FrameTimes times_;                // the newest complete times, kept across frames
  FrameReport report_;
  PassHook pass_hook_;
  std::string source_definitions_;
  // GlStateGuards of this chain alive now: while there is one, render() leaves saving the
  // engine's state to it.
  mutable int guards_ = 0;
};

}  // namespace pfx::host
