// Draws the chain's HDR output into the window: exposure, tone curve and sRGB encoding in a
// shader that follows host/lib/image/tonemap.hpp's rules (NaN pixels magenta, +inf white, negative
// black); or, for an 8-bit picture, the chain's sRGB codes as they are (pfx-render writes them so
// from a PNG: exposure and tone do not apply). Scaled to fit the window with the frame's aspect
// kept (nearest pixel: inf and NaN must not spread to neighbours through filter weights of zero).
#pragma once

#include <cstdint>

#include "tonemap.hpp"

namespace pfx::app {

struct Viewport {
  int x = 0, y = 0, width = 1, height = 1;  // in window pixels, origin bottom-left (GL)
};

// The largest rectangle of the frame's aspect that fits the window, centred.
Viewport fit_viewport(int frame_width, int frame_height, int window_width, int window_height);

class DisplayPass {
 public:
  DisplayPass();  // GL context current
  ~DisplayPass();
  DisplayPass(const DisplayPass&) = delete;
  DisplayPass& operator=(const DisplayPass&) = delete;
  bool ok() const { return program_ != 0; }

  // Clears the default framebuffer and draws texture (RGBA16F) into viewport.
  void draw(uint32_t texture, const Viewport& viewport, int window_width, int window_height,
            const ToneMapSettings& tone) const;
  // The same for a texture of 8-bit codes (RGBA8, sampled as stored).
  void draw_codes(uint32_t texture, const Viewport& viewport, int window_width, int window_height) const;

 private:
  void draw_texture(uint32_t texture, const Viewport& viewport, int window_width, int window_height,
                    const ToneMapSettings& tone, bool codes) const;
  uint32_t program_ = 0, vertex_array_ = 0, sampler_ = 0;
};

}  // namespace pfx::app
