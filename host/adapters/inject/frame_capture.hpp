// --capture: for a chosen presented frame, the application's frame as the chain received it
// (PREFIX.app.exr, linear half float), the chain's output before it was encoded back
// (PREFIX.out.exr) and what was presented (PREFIX.png). Each file appears whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "image.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

// An RGBA16F texture of width x height as a half-float EXR. False with *error.
bool write_texture_exr(GLuint texture, int width, int height, const std::string& path, std::string* error);
bool write_presented_png(const app::DisplayImage& image, const std::string& path, std::string* error);

}  // namespace pfx::inject
