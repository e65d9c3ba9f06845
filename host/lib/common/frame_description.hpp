// The pfx_frame a host hands the chain (pfx/effect.h), filled the same way by every host of
// ours: pfx-render, pfx-view, pfx-bench, pfx-validate, pfx-inject and the video-host adapters.
// Header-only, so that the scene library below pfx_common can use it too.
#pragma once

#include <cstdint>

#include <pfx/effect.h>

namespace pfx::app {

// Every input a renderer with a whole G-buffer gives: colour, depth, normals, albedo, emission
// and the lights.
constexpr uint32_t kEveryInput = PFX_INPUT_COLOR | PFX_INPUT_DEPTH | PFX_INPUT_NORMAL | PFX_INPUT_ALBEDO |
                                 PFX_INPUT_EMISSIVE | PFX_INPUT_LIGHTS;

// A width x height frame with `inputs` (PFX_INPUT_* bits) seen through `camera`. Its depth is
// stored as `depth_encoding` when the inputs hold depth, else there is none. No lights (the
// light record's size is set, so a host with lights sets only lights and light_count), time 0
// and frame index 0 until the caller says otherwise.
inline pfx_frame describe_frame(int width, int height, uint32_t inputs, pfx_depth_encoding depth_encoding,
                                const pfx_camera& camera) {
  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = static_cast<uint32_t>(width);
  frame.height = static_cast<uint32_t>(height);
  frame.inputs = inputs;
  frame.depth_encoding = (inputs & PFX_INPUT_DEPTH) ? depth_encoding : pfx_depth_encoding{PFX_DEPTH_NONE};
  frame.camera = camera;
  frame.light_struct_size = sizeof(pfx_light);
  return frame;
}

}  // namespace pfx::app
