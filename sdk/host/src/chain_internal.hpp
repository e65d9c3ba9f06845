// What chain.cpp (instances, declare, plan) and chain_execute.cpp (running the plan) share: the
// chain's private types.
#pragma once

#include <string>

#include <glad/gl.h>

#include "frame_conversion.hpp"
#include "gl_pool.hpp"
#include "gl_state_scope.hpp"
#include "gpu_timer.hpp"
#include "pfx/host/chain.hpp"

namespace pfx::host {

struct Chain::Instance {
  // Copied, not a pointer into the registry's index, which a load or reload rebuilds.
  EffectInfo info;
  void* handle = nullptr;
  bool enabled = true;
  Declaration declaration;
  bool has_declaration = false;
  // Which instance of its effect this is (from 1, in chain order) and its name, "bloom#2": the
  // store's instance it reads its values from.
  size_t number = 1;
  std::string name;
  // The store holds a block for every instance its chain holds: never null.
  const pfx_value* values(const ParamStore& params) const { return params.values(info.desc->id, number); }
};

struct Chain::GlResources {
  GlPool pool;
  GlLimits limits = GlLimits::query();
  GpuTimer timer;
  FrameConversion conversion;
};

// Where render() was told to put the result: a texture, or a framebuffer (FramebufferOutput).
struct HostOutput {
  GLuint texture = 0;
  bool to_framebuffer = false;
  GLuint framebuffer = 0;
  bool srgb = false;  // the framebuffer holds sRGB codes
};

// How the host's colour reaches the first effect, and the last effect's result the host's output
// (frame_ends.hpp): as they are, or through one step of the chain's.
enum class ColorStep {
  AS_IS,
  WIDEN,       // 8-bit colour drawn into the chain's RGBA16F copy, for a linear effect
  COPY_CODES,  // 8-bit sRGB colour copied as codes, for a display-referred effect (no view could be made)
  ENCODE,      // linear colour encoded into codes, for a display-referred effect
};
enum class OutputStep {
  AS_IS,
  NARROW,      // the chain's RGBA16F result drawn into the host's 8-bit output
  COPY_CODES,  // the chain's codes copied into the host's 8-bit sRGB output as they are
  DECODE,      // the chain's codes decoded into the host's linear output
};

// The textures one render() runs over: the frame's inputs, the chain's output, the plan's pooled
// targets.
struct FrameResources {
  const pfx_frame& frame;
  const FrameTextures& textures;
  const HostOutput& output;  // the host's
  const FramePlan& plan;
  GlPool& pool;
  // What the first effect's "color" and the last effect's "output" are bound to this frame: the
  // host's texture or framebuffer, a raw view of it, or the chain's copies (frame_ends.hpp).
  GLuint color_bound = 0, output_bound = 0;
  bool output_to_framebuffer = false;  // the last effect draws into output.framebuffer, not output_bound
  bool output_eight_bit = false;  // the output the last effect writes is 8-bit (PFX_FORMAT_RGBA8)
  bool output_srgb_writes = false;  // passes into it draw with GL_FRAMEBUFFER_SRGB
  ColorStep color_step = ColorStep::AS_IS;
  OutputStep output_step = OutputStep::AS_IS;
  // Raw (GL_RGBA8) views of the host's sRGB textures, made for this frame and deleted after it: a
  // kept view would hold on to the storage of a texture the host deleted.
  GLuint color_view = 0, output_view = 0;
};

}  // namespace pfx::host
