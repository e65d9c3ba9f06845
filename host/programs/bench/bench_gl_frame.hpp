// One pfx-bench frame on the GPU: its textures and description for the chains, with bottom-first
// copies of its colour and depth (for the CPU references, pfx/reference.h) and of its truth and
// halo mask (for comparing with outputs read back from GL).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <pfx/host/chain.hpp>

#include "bench_frames.hpp"
#include "camera_options.hpp"
#include "display_frame.hpp"

namespace pfx::bench {

struct GlBenchFrame {
  int width = 0, height = 0;
  // RGBA16F textures: the frame in linear light and a target of its size, between which the copy
  // pass (the unit) is timed; for an EXR or the demo image also what the chains read and write.
  uint32_t color = 0, depth = 0, output = 0;
  // For an 8-bit frame (a PNG): its codes in 8-bit textures as hosts of 8-bit frames hand them to
  // the chain (display_frame.hpp), which reads and writes these instead.
  std::unique_ptr<pfx::gl::DisplayFrame> display;
  std::vector<float> color_gl, depth_gl, truth_gl;  // rows bottom first; depth and truth may be empty
  std::vector<uint8_t> mask_gl;                     // rows bottom first; may be empty
  pfx_frame frame{};
  pfx::host::FrameTextures textures;

  bool eight_bit() const { return display != nullptr; }
  // The texture the chains render into.
  uint32_t chain_output() const { return display ? display->output() : output; }
  // What a chain wrote, in linear light, rows bottom first: an 8-bit result encoded as its host
  // would take it and decoded exactly.
  std::vector<float> read_result() const;
};

// Needs a current GL context; release_gl_bench_frame deletes what it created. False with *error when
// the 8-bit frame's programs do not build.
bool upload_gl_bench_frame(const BenchFrame& input, const pfx::app::CameraOptions& camera, GlBenchFrame* gl,
                           std::string* error);
void release_gl_bench_frame(GlBenchFrame& frame);

}  // namespace pfx::bench
