// The frames pfx-bench measures on: the built-in demo image at each --sizes size, or the --input
// files, each with its optional ground truth and halo mask (bench_options.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "image.hpp"

namespace pfx::bench {

struct BenchFrame {
  std::string source;              // "demo image" or the input's path
  pfx::app::Image image;           // rows top first; depth may be empty
  std::vector<float> truth;        // empty, or RGBA of the image's size, rows top first
  std::vector<uint8_t> halo_mask;  // empty, or one per pixel (non-zero on the object), rows top first
};

// False with *error naming the file for an input that cannot be read or whose truth or mask has
// another size (pfx-bench exits 3 then).
bool make_bench_frames(const BenchOptions& options, std::vector<BenchFrame>* frames, std::string* error);

}  // namespace pfx::bench
