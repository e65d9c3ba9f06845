// The two textures the viewer's chain draws into, one shown while the other is drawn, so a frame
// that fails leaves the last good one on screen. For an HDR frame they hold linear light
// (RGBA16F); for an 8-bit picture they hold 8-bit sRGB codes, which the chain writes through an
// sRGB view (a display-referred last effect writes its codes as they are), and which are shown and
// saved as pfx-render writes them from the same picture. The GL context must be current.
#pragma once

#include <cstdint>

#include "eight_bit_texture.hpp"
#include "image.hpp"

namespace pfx::app {

class ViewOutput {
 public:
  ViewOutput() = default;
  ~ViewOutput();
  ViewOutput(const ViewOutput&) = delete;
  ViewOutput& operator=(const ViewOutput&) = delete;

  // Matches the textures to the frame: a no-op when neither the size nor the kind changed.
  void resize(int width, int height, bool codes);
  int width() const { return width_; }
  int height() const { return height_; }
  bool codes() const { return codes_; }

  // What the chain draws into next; swap() shows it.
  uint32_t target() const;
  void swap();
  // What is shown: RGBA16F in linear light, or for codes the plain RGBA8 texture of them (sampled
  // as it is stored, so the window shows the codes, not a decoded and encoded again copy).
  uint32_t shown() const;
  bool has_frame() const { return shown() != 0; }

  // The shown frame read back: in linear light (codes are decoded with the exact sRGB curve), and
  // for codes the bytes themselves with `channels` (3 or 4) channels, row 0 at the top.
  Image linear() const;
  DisplayImage encoded(int channels) const;

 private:
  void release();

  bool codes_ = false;
  int width_ = 0, height_ = 0;
  uint32_t linear_[2] = {0, 0};
  gl::EightBitTexture eight_bit_[2];
  int front_ = 0;
};

}  // namespace pfx::app
