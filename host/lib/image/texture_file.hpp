// Texture files as models ship them: PNG (libpng), JPEG (libjpeg-turbo), TGA and BMP (Debian's
// stb_image), read into 8-bit pixels. The format is taken from the file's first bytes (a ".jpg" that is really a PNG
// is read as PNG); TGA, which has no signature, from the name's extension ".tga".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "image.hpp"

namespace pfx::app {

// Textures above this many pixels are refused before their pixels are decoded (64 Mi, as PNG input).
constexpr std::int64_t kMaxTexturePixels = std::int64_t{1} << 26;

// Reads the file: RGB, or RGBA when it has an alpha channel (straight alpha); grey becomes RGB.
// Row 0 is the top row as the file shows it. The values are the file's codes, not yet linear.
// False with *problem ("PATH: REASON", never empty) when the file is missing, of another format,
// damaged or truncated, or too large; *out is then unchanged. Never throws, never aborts.
bool read_texture_file(const std::string& path, DisplayImage* out, std::string* problem,
                       std::int64_t max_pixels = kMaxTexturePixels);

// The same for a JPEG, TGA or BMP file's bytes in memory (PNG only from files). `tga` says the
// bytes are a TGA file (it has no signature to find). *problem is the reason alone.
bool decode_texture_bytes(const std::uint8_t* data, std::size_t size, bool tga, DisplayImage* out,
                          std::string* problem, std::int64_t max_pixels = kMaxTexturePixels);

}  // namespace pfx::app
