// OpenEXR input and output for scene-linear frames.
//
// Reading colour (ExrRequest::Role::Color, what --input takes). A "layer" is the part of a channel
// name before its last dot ("diffuse" of "diffuse.R"); the plain channels are those without a dot.
// Which channels, in this order:
//   - with a layer named (ExrRequest::layer): the part of that name, else the first part holding a
//     layer of that name; in a part so named, its layer of the same name if it has one, else as
//     below. No such part or layer: refused, listing the layers and parts.
//   - else, in the first part: the plain channels when they hold R, G, B or Y; else the one layer
//     that does; else the part's single channel, whatever its name. Several layers with colour and
//     none plain: refused, listing them (the caller names one). Nothing at all: refused, listing
//     the channels.
// Within the layer taken:
//   - R, G, B: as they are. Only some of them: those in their own places and the others 0, as a
//     compositor shows a lone channel (a G-only file is green, not grey).
//   - Y (luminance), no R, G, B: grey. With RY and/or BY (OpenEXR's luminance/chroma images):
//     converted to RGB with the file's chromaticities (Rec. 709 when it has none), the way
//     OpenEXR's RgbaInputFile does; a missing RY or BY counts as 0.
//   - neither, and a single channel (a matte, a depth pass, "A" alone): grey.
//   - A when the layer has one, else alpha 1. X, Y, Z in a layer that also has X are a vector's
//     axes: its Y is not luminance and its Z is not depth.
//   - depth (Image::depth): the layer's Z, else the depth that Role::Depth's first three steps
//     find in the same part; none: no depth.
// Reading depth (Role::Depth, what --depth takes): Image::depth only, rgba left empty. The first
// of: Z; a channel named "depth" (any case) or the Z of a layer named so ("ViewLayer.Depth.Z");
// the Z of any other layer (not a vector's) -- each looked for in every part in turn -- then in
// the first part: R; Y; its single channel.
// Half, float and uint channels are read as float (uint converted exactly up to 2^24). A channel
// stored at less than full resolution (x/y sampling above 1) is interpolated linearly between its
// samples. Tiled and mip-mapped parts give their full-resolution level; deep parts are refused.
// The output always has the DISPLAY window's size, with the display window's top-left
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

// What read_exr takes from a file (see the top of this header).
struct ExrRequest {
  enum class Role { Color, Depth };
  Role role = Role::Color;
  std::string layer;  // Color only: a part or layer name; empty for the default choice
  ExrLimits limits;
};

// Reads `path` into *out. On failure returns false, leaves *out unchanged and sets *error to
// "PATH: REASON" (missing file, not an OpenEXR file, damaged or truncated, no channels to read
// (listing those it has), window larger than `limits`...). On success *used (when not null) says
// in words which channels were read, e.g. "layer 'diffuse': R, G, B (no A: alpha 1); depth Z".
// Never throws.
bool read_exr(const std::string& path, Image* out, std::string* error, const ExrRequest& request,
              std::string* used);

// Colour, the default choice.
bool read_exr(const std::string& path, Image* out, std::string* error,
              const ExrLimits& limits = {});

// Writes `img` to `path` (see above). On failure returns false, leaves any existing file at
// `path` untouched and sets *error. Never throws.
bool write_exr(const std::string& path, const Image& img, ExrPixelType type, std::string* error);

}  // namespace pfx::app
