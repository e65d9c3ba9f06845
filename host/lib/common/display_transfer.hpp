// How the 8-bit values of a display-referred frame (an application's back buffer, a video frame)
// relate to light. Every host that takes such frames (pfx-inject, the video-host adapters,
// pfx-render with an 8-bit --input) names it the same way and converts with transfer_programs.
#pragma once

#include <string>

#include "image.hpp"

namespace pfx::app {

enum class Transfer {
  SRGB,    // sRGB-encoded (what almost every application and video presents): decoded with the
           // exact piecewise sRGB curve, encoded back with its inverse
  LINEAR,  // the values are linear light: divided by 255, multiplied back
};

// "x.png" (any case): the inputs our programs read as 8-bit display-referred frames (a frame a
// video tool wrote, a photograph), decoded by a transfer rather than read as EXR.
bool is_display_input(const std::string& path);

// "srgb" or "linear"; false with *error naming what was given.
bool parse_transfer(const std::string& text, Transfer* out, std::string* error);
const char* transfer_name(Transfer transfer);

// 8-bit codes back in linear light with the exact curve, as the transfer reads them: RGBA, an RGB
// image opaque, alpha never curved; rows in the image's order. For reports and captures of frames
// the GPU kept in 8 bits.
Image decode_display_image(const DisplayImage& encoded, Transfer transfer);

}  // namespace pfx::app
