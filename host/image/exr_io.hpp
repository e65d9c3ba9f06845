// OpenEXR input and output for scene-linear frames.
//
// Reading: RGB or RGBA (A missing -> 1), or luminance-only Y (read as grey); half, float or uint
// channels; a `Z` channel, when present, becomes Image::depth (linear view depth in metres).
// Tiled and mip-mapped files give their full-resolution level; a multi-part file gives its first
// part. The output always has the DISPLAY window's size, with the display window's top-left
// corner at row 0, column 0. Pixels of the display window that the data window does not cover
// are "nothing there": rgba = (0, 0, 0, 0) and depth = +inf. Parts of the data window outside the
// display window are dropped.
//
// Writing: R, G, B, A as half (default) or float, plus Z as float when the image has depth;
// ZIP compression; display window = data window = (0,0)-(w-1,h-1). Half storage converts each value
// with Imath's half(float): round to nearest even; magnitudes that round past the half maximum
// (65504, i.e. from 65520 up) become +/-inf; NaN stays NaN. Nothing else is changed. The file appears atomically
// (atomic_file.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "image.hpp"

namespace pfx::app {

enum class ExrPixelType { Half, Float };

// What read_exr accepts before it allocates anything. Both the display and the data window are
// checked against these, from the header alone.
struct ExrLimits {
  // Width or height of either window, in pixels.
  std::int64_t max_dimension = 65536;
  // Area of either window, in pixels. 2^26 = 67,108,864 (8192 x 8192); the decoded image then
  // takes at most 1.25 GiB (RGBA + depth as float).
  std::int64_t max_pixels = std::int64_t{1} << 26;
};

// Reads `path` into *out. On failure returns false, leaves *out unchanged and sets *error to
// "PATH: REASON" (missing file, not an OpenEXR file, damaged or truncated, unsupported layout,
// window larger than `limits`...). Never throws.
bool read_exr(const std::string& path, Image* out, std::string* error,
              const ExrLimits& limits = {});

// Writes `img` to `path` (see above). On failure returns false, leaves any existing file at
// `path` untouched and sets *error. Never throws.
bool write_exr(const std::string& path, const Image& img, ExrPixelType type, std::string* error);

}  // namespace pfx::app
