// JPEG files in memory through libjpeg-turbo (Debian's libjpeg62-turbo): baseline, progressive,
// grey or colour, decoded to 8-bit RGB.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "image.hpp"

namespace pfx::app {

// False with *problem (the reason, never empty) when the bytes are not a JPEG libjpeg can decode,
// when the file ends before its last scan (libjpeg would fill the rest with grey), or when the
// image has more than max_pixels pixels (refused before any pixel is decoded).
bool decode_jpeg(const std::uint8_t* data, std::size_t size, std::int64_t max_pixels, DisplayImage* out,
                 std::string* problem);

}  // namespace pfx::app
