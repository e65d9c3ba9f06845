#include "display_transfer.hpp"

#include <array>
#include <cctype>
#include <cmath>

namespace pfx::app {

bool parse_transfer(const std::string& text, Transfer* out, std::string* error) {
  if (text == "srgb") *out = Transfer::SRGB;
  else if (text == "linear") *out = Transfer::LINEAR;
  else {
    *error = "transfer '" + text + "': expected srgb or linear";
    return false;
  }
  return true;
}

const char* transfer_name(Transfer transfer) { return transfer == Transfer::SRGB ? "srgb" : "linear"; }

Image decode_display_image(const DisplayImage& encoded, Transfer transfer) {
  // The exact piecewise sRGB curve (IEC 61966-2-1).
  std::array<float, 256> linear{};
  for (int code = 0; code < 256; ++code) {
    const double v = code / 255.0;
    linear[code] = static_cast<float>(transfer == Transfer::LINEAR ? v
                                      : v <= 0.04045            ? v / 12.92
                                                                 : std::pow((v + 0.055) / 1.055, 2.4));
  }
  Image image;
  image.width = encoded.width;
  image.height = encoded.height;
  const size_t count = static_cast<size_t>(encoded.width) * encoded.height;
  image.rgba.assign(count * 4, 1.0f);
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* pixel = &encoded.pixels[i * encoded.channels];
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = linear[pixel[c]];
    if (encoded.channels == 4) image.rgba[i * 4 + 3] = pixel[3] / 255.0f;
  }
  return image;
}

bool is_display_input(const std::string& path) {
  if (path.size() < 4) return false;
  std::string extension = path.substr(path.size() - 4);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".png";
}

}  // namespace pfx::app
