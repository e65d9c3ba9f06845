#pragma once
// The image file an FX texture names with `source = "file.png"`, decoded for either runtime: 8-bit
// RGBA texels at the size the texture declares (the image scaled to it, nearest texel), top row
// first as FX and Vulkan count. A 3D texture's slices lie side by side in the image, as LUT
// images do (its width is the texture's width times its depth); the texels come slice by slice.
// PNG, JPEG, BMP and TGA, through Debian's stb_image.
#include <string>
#include <vector>

namespace pfx::fx {

struct TextureTexels {
  int width = 1, height = 1, depth = 1;
  std::vector<unsigned char> rgba;  // width * height * depth * 4
};

// Decodes `path` into `out` for a texture of width x height x depth. False with `error` when the
// file cannot be read or decoded.
bool decode_texture_image(const std::string& path, int width, int height, int depth, TextureTexels& out, std::string& error);

}  // namespace pfx::fx
