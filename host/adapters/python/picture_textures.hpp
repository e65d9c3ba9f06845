// The textures a Chain runs a float picture through (its colour, its depth, the chain's output),
// kept from one run to the next: a loop over frames of one size makes them once, not once a run.
// Every call on the Chain's GL thread.
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/host/chain.hpp>

#include "image.hpp"

namespace pfx::python {

class PictureTextures {
 public:
  // Uploads the picture's colour (`channels` floats a pixel, row 0 at the top; null for an 8-bit
  // picture, decoded elsewhere) and its depth (where `picture` has one) into textures of its size,
  // made anew only when the size or what the picture holds changed; the output texture goes with
  // the colour.
  void upload(const app::Image& picture, const float* colour, int channels);
  // The output texture into `out`: `channels` floats a pixel (alpha left out with 3), row 0 at the top.
  void download(float* out, int channels);
  host::FrameTextures inputs() const;
  uint32_t output() const { return output_; }
  // Deletes the textures (the context must still be current).
  void release();

 private:
  uint32_t color_ = 0, depth_ = 0, output_ = 0;
  int width_ = 0, height_ = 0;
  // RGBA rows bottom first, as GL takes and gives them: kept, so that a loop over frames does not
  // fault in fresh pages at every call.
  std::vector<float> staging_;
};

}  // namespace pfx::python
