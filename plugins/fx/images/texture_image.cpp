#include "texture_image.hpp"

#include <fstream>
#include <iterator>

#include <stb/stb_image.h>

namespace pfx::fx {

bool decode_texture_image(const std::string& path, int width, int height, int depth, TextureTexels& out, std::string& error) {
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = bytes.empty() ? nullptr : stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!pixels) {
    error = "cannot read '" + path + "': " + (bytes.empty() ? std::string("empty or unreadable") : stbi_failure_reason());
    return false;
  }
  out.width = width, out.height = height, out.depth = depth;
  out.rgba.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(depth) * 4, 0);
  const long long row_of_tiles = static_cast<long long>(width) * depth;  // the image's width, in texels of the texture
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const long long tx = static_cast<long long>(z) * width + x;  // slice z is the z-th tile of the row
        const auto sx = static_cast<std::size_t>(tx * w / row_of_tiles), sy = static_cast<std::size_t>(static_cast<long long>(y) * h / height);
        const unsigned char* from = pixels + (sy * static_cast<std::size_t>(w) + sx) * 4;
        unsigned char* to = out.rgba.data() + ((static_cast<std::size_t>(z) * height + y) * width + x) * 4;
        for (int c = 0; c < 4; ++c) to[c] = from[c];
      }
  stbi_image_free(pixels);
  return true;
}

}  // namespace pfx::fx
