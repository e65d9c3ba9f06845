// 8-bit PNG files for display output and for comparing against expected pictures.
// Uses libpng's simplified API, which reports errors by return value rather than longjmp, so no
// libpng error can unwind through C++ frames.
#pragma once

#include <cstdint>
#include <string>

#include "image.hpp"

namespace pfx::app {

// Writes an 8-bit RGB or RGBA PNG tagged as sRGB, atomically (atomic_file.hpp). The pixels are
// taken as already sRGB-encoded (see tonemap.hpp). On failure returns false, leaves any existing
// file untouched and sets *error. Never throws.
bool write_png(const std::string& path, const DisplayImage& img, std::string* error);

// Reads any PNG as 8-bit sRGB: RGBA when the file has alpha (or transparency), RGB otherwise;
// grey becomes RGB, 16-bit is reduced to 8. Files larger than max_pixels are refused before any
// pixel memory is allocated. On failure returns false, leaves *out unchanged and sets *error to
// "PATH: REASON".
bool read_png(const std::string& path, DisplayImage* out, std::string* error,
              std::int64_t max_pixels = std::int64_t{1} << 26);

}  // namespace pfx::app
