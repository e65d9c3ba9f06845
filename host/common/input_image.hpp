// An input image as our programs take it: --input IMG.exr, optionally with --depth DEPTH.exr.
#pragma once

#include <string>

#include "exr_io.hpp"
#include "image.hpp"

namespace pfx::app {

// Reads the EXR at `input`; when `depth_path` is not empty, its Z channel (else its R channel)
// becomes the image's linear depth. Both files are checked against `limits` before anything is
// allocated. False with *error "PATH: reason" (sizes that differ included).
bool read_input_image(const std::string& input, const std::string& depth_path, Image* image, std::string* error,
                      const ExrLimits& limits = {});

}  // namespace pfx::app
