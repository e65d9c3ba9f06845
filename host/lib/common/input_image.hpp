// An input image as our programs take it: --input IMG.exr [--layer NAME], optionally with
// --depth DEPTH.exr. Which channels of each file are read is read_exr's rule (exr_io.hpp).
#pragma once

#include <string>

#include "exr_io.hpp"
#include "image.hpp"

namespace pfx::app {

struct InputFiles {
  std::string input;  // colour (and depth, when it has some and `depth` is empty)
  std::string layer;  // a part or layer of `input`; empty for the default choice
  std::string depth;  // empty, or a file whose depth replaces the input's
  ExrLimits limits;   // for both files, checked before anything is allocated
};

// What was read, in words, for the log or a JSON report.
struct InputReport {
  std::string color;  // e.g. "R, G, B, A; depth Z"
  std::string depth;  // e.g. "depth R" when --depth was given, else empty
};

// False with *error "PATH: reason" (sizes that differ included).
bool read_input_image(const InputFiles& files, Image* image, InputReport* report, std::string* error);

}  // namespace pfx::app
