// One pfx-bench frame on the GPU: its textures and description for the chains, with bottom-first
// copies of its colour and depth (for the CPU references, pfx/reference.h) and of its truth and
// halo mask (for comparing with outputs read back from GL).
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/host/chain.hpp>

#include "bench_frames.hpp"
#include "camera_options.hpp"

namespace pfx::bench {

struct GlBenchFrame {
  int width = 0, height = 0;
  uint32_t color = 0, depth = 0, output = 0;        // textures; output is where every chain renders
  std::vector<float> color_gl, depth_gl, truth_gl;  // rows bottom first; depth and truth may be empty
  std::vector<uint8_t> mask_gl;                     // rows bottom first; may be empty
  pfx_frame frame{};
  pfx::host::FrameTextures textures;
};

// Needs a current GL context; release_gl_bench_frame deletes what it created.
GlBenchFrame upload_gl_bench_frame(const BenchFrame& input, const pfx::app::CameraOptions& camera);
void release_gl_bench_frame(const GlBenchFrame& frame);

}  // namespace pfx::bench
