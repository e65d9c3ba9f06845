// An input image as our programs take it: --input IMG.exr, optionally with --depth DEPTH.exr.
#pragma once

#include <string>

#include "image.hpp"

namespace pfx::app {

// Reads the EXR at `input`; when `depth_path` is not empty, its Z channel (else its R channel)
// becomes the image's linear depth. False with *error "PATH: reason" (sizes that differ included).
bool read_input_image(const std::string& input, const std::string& depth_path, Image* image, std::string* error);

}  // namespace pfx::app
