#pragma once
// The image a preset's lookup texture names, decoded to 8-bit RGBA, top row first (as RetroArch
// loads it and as the chain stores pictures, lr_textures.hpp). PNG, JPEG, BMP and TGA through
// Debian's stb_image, at most 16384 pixels a side.
#include <string>
#include <vector>

namespace pfx_libretro {

struct DecodedImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
};

// False with "cannot read 'file': why" in *error.
bool decode_image(const std::string& path, DecodedImage* out, std::string* error);

}  // namespace pfx_libretro
