#include "lr_images.hpp"

#include <fstream>
#include <iterator>

#include <stb/stb_image.h>

namespace pfx_libretro {

bool decode_image(const std::string& path, DecodedImage* out, std::string* error) {
  std::ifstream file(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = bytes.empty() ? nullptr
                                        : stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h,
                                                                &channels, 4);
  if (!pixels) {
    *error = "cannot read '" + path +
             "': " + (bytes.empty() ? std::string("missing, empty or unreadable") : stbi_failure_reason());
    return false;
  }
  out->width = w, out->height = h;
  out->rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return true;
}

}  // namespace pfx_libretro
