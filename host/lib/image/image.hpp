// The in-memory images our programs pass around: scene-linear HDR frames (Image) and 8-bit
// display frames (DisplayImage).
//
// Row order: row 0 is the TOP row, as OpenEXR and PNG store it. GL's origin is the bottom-left,
// so code that uploads to or reads back from GL flips rows; nothing in host/lib/image does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pfx::app {

struct Image {
  int width = 0;
  int height = 0;
  // width * height * 4 floats, RGBA interleaved, linear scene-referred colour (alpha as stored
  // in the file; EXR convention is premultiplied).
  std::vector<float> rgba;
  // Empty, or width * height floats: linear view depth in metres (distance along the view axis).
  // +inf means "nothing there".
  std::vector<float> depth;

  bool has_depth() const { return !depth.empty(); }
  std::size_t pixel_count() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  // True when the vectors match the declared size (what the writers require).
  bool is_consistent() const {
    if (width < 0 || height < 0) return false;
    return rgba.size() == pixel_count() * 4 && (depth.empty() || depth.size() == pixel_count());
  }
};

// 8-bit sRGB-encoded pixels for display and PNG files, interleaved, row 0 = top.
struct DisplayImage {
  int width = 0;
  int height = 0;
  int channels = 3;  // 3 (RGB) or 4 (RGBA, straight alpha as PNG defines it)
  std::vector<std::uint8_t> pixels;

  bool is_consistent() const {
    if (width < 0 || height < 0 || (channels != 3 && channels != 4)) return false;
    return pixels.size() ==
           static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels;
  }

  // The pixels as RGBA: a picture without alpha is opaque (what a video tool hands a filter).
  std::vector<std::uint8_t> rgba_pixels() const {
    if (channels == 4) return pixels;
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<std::uint8_t> rgba(count * 4);
    for (std::size_t i = 0; i < count; ++i) {
      for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = pixels[i * 3 + c];
      rgba[i * 4 + 3] = 255;
    }
    return rgba;
  }

  // An RGBA picture becomes RGB, its alpha left out.
  void drop_alpha() {
    if (channels != 4) return;
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < 3; ++c) pixels[i * 3 + c] = pixels[i * 4 + c];
    pixels.resize(count * 3);
    channels = 3;
  }
};

}  // namespace pfx::app
