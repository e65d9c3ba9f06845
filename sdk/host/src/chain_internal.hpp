// What chain.cpp (instances, declare, plan) and chain_execute.cpp (running the plan) share: the
// chain's private types.
#pragma once

#include <string>

#include <glad/gl.h>

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
};

// The textures one render() runs over: the frame's inputs, the chain's output, the plan's pooled
// targets.
struct FrameResources {
  const pfx_frame& frame;
  const FrameTextures& textures;
  GLuint output_texture;
  const FramePlan& plan;
  GlPool& pool;
};

}  // namespace pfx::host
