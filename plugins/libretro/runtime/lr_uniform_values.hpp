#pragma once
// The values a pass's uniform block and push constants get in one frame, written at the offsets
// the reflection found, with the types the slang format gives them (slang_semantics.hpp).
#include <cstdint>
#include <vector>

#include "chain_plan.hpp"
#include "slang_reflection.hpp"

namespace pfx_libretro {

struct PassValues {
  const float* mvp = nullptr;  // 16 floats, column-major
  pfx::libretro::PixelSize output, source, original, viewport;
  const std::vector<pfx::libretro::PixelSize>* pass_sizes = nullptr;  // this frame's, per pass
  const std::vector<pfx::libretro::PixelSize>* lookup_sizes = nullptr;
  const std::vector<double>* parameters = nullptr;  // per shader parameter id
  std::uint32_t frame_count = 0;                    // after the pass's frame_count_mod
  std::int32_t frame_direction = 1;
  std::uint32_t frame_time_delta_us = 0;
  float original_fps = 60;
};

// The size a size semantic (OutputSize, SourceSize, PassOutputSize2...) stands for this frame.
pfx::libretro::PixelSize semantic_size(const pfx::libretro::Semantic& semantic, const PassValues& values);

// Writes every member of `block` into `bytes` (block.size bytes).
void write_block_values(const pfx::libretro::ReflectedBlock& block, const PassValues& values,
                        std::vector<unsigned char>& bytes);

}  // namespace pfx_libretro
