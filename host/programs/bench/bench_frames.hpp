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
  // A PNG input: its 8-bit RGBA codes, rows top first (sRGB-encoded, as a video or an application
  // hands its frame over). The chain then runs on the 8-bit frame as every host of 8-bit frames runs
  // it, with the display-referred defaults; `image` holds the codes decoded exactly, for the
  // references and the unit. Empty for an EXR or the demo image.
  pfx::app::DisplayImage display;
};

// An --input ending in .png is read as an 8-bit frame, anything else as an EXR.
// False with *error naming the file for an input that cannot be read or whose truth or mask has
// another size (pfx-bench exits 3 then).
bool make_bench_frames(const BenchOptions& options, std::vector<BenchFrame>* frames, std::string* error);

}  // namespace pfx::bench
