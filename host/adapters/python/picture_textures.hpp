// The textures a Chain runs a float picture through (its colour, its depth, the chain's output),
// kept from one run to the next: a loop over frames of one size makes them once, not once a run.
// Every call on the Chain's GL thread.
#pragma once

#include <cstdint>

#include <pfx/host/chain.hpp>

#include "image.hpp"

namespace pfx::python {

class PictureTextures {
 public:
  // Uploads the picture's colour (where picture.rgba holds it: an 8-bit picture's is decoded
  // elsewhere) and its depth (where it has one) into textures of its size, made anew only when the
  // size or what the picture holds changed; the output texture goes with the colour.
  void upload(const app::Image& picture);
  host::FrameTextures inputs() const;
  uint32_t output() const { return output_; }
  // Deletes the textures (the context must still be current).
  void release();

 private:
  uint32_t color_ = 0, depth_ = 0, output_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::python
