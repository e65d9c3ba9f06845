// --capture: for a chosen presented frame, the application's frame as the chain received it
// (PREFIX.app.exr, linear half float, its 8-bit codes decoded with the exact curve), the chain's
// output (PREFIX.out.exr, the same) and what was presented (PREFIX.png). Each file appears whole or
// not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

// A linear image as a half-float EXR. False with *error.
bool write_image_exr(const app::Image& image, const std::string& path, std::string* error);
bool write_presented_png(const app::DisplayImage& image, const std::string& path, std::string* error);

}  // namespace pfx::inject
