// The files the viewer writes: a frame as pfx-render writes it (PNG tone-mapped and EXR
// scene-linear, side by side), numbered screenshot names, and a picture of the whole window.
// Every file is written to a temporary name and renamed when complete.
#pragma once

#include <string>

#include "image.hpp"
#include "tonemap.hpp"

namespace pfx::app {

// "shot.png" -> "shot.exr" (any other name gets ".exr" appended).
std::string exr_beside(const std::string& png_path);

// Writes png_path (tone-mapped with `tone`, as pfx-render --out FILE.png) and the half-float EXR
// beside it. False with *error naming the file.
bool write_frame_pair(const Image& frame, const std::string& png_path, const ToneMapSettings& tone, std::string* error);

// "DIR/pfx-view-0001" with the first number for which none of .png, .exr, .json exists yet.
std::string next_screenshot_base(const std::string& directory);

// Reads the current back buffer of the default framebuffer (width x height) and writes it as PNG.
bool write_window_png(int width, int height, const std::string& path, std::string* error);

}  // namespace pfx::app
