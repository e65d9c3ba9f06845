// The GPU side of display_transfer.hpp: the two full-screen programs that turn a display-referred
// RGBA8 texture into the chain's linear RGBA16F `color` and the chain's output back into 8 bits.
// One implementation for every host that takes 8-bit frames, so pfx-inject, the video-host
// adapters and pfx-render give the same bytes for the same frame.
#pragma once

#include <string>

#include <glad/gl.h>

#include "display_transfer.hpp"

namespace pfx::gl {

class TransferPrograms {
 public:
  // Compiles both programs and an empty vertex array; false with *error when the context lacks
  // what they need. The context must stay current for every call below and the destructor.
  bool create(std::string* error);
  ~TransferPrograms();

  // Each draws one full-screen triangle into the bound draw framebuffer over the current
  // viewport, reading `source` texel for texel at the same pixel (texelFetch at gl_FragCoord):
  // binds its program, the vertex array and texture unit 0, and leaves them bound.
  //   decode: RGBA8 (display-referred) -> linear light, for an RGBA16F target
  //   encode: linear light -> display-referred, for an RGBA8 (or RGB10_A2) target (clamped to
  //           [0, 1]; NaN -> 0)
  // flip_rows = H (the frame's height) reads the source's row H-1-y for row y instead: video
  // frames and image files keep their top row first, where GL keeps its bottom row, so a frame
  // uploaded as stored is decoded the right way up, and encoded back into the stored order, by
  // flipping. 0: no flip.
  void decode(GLuint source, app::Transfer transfer, int flip_rows = 0) const;
  void encode(GLuint source, app::Transfer transfer, int flip_rows = 0) const;

 private:
  GLuint decode_program_ = 0, encode_program_ = 0, vertex_array_ = 0;
};

}  // namespace pfx::gl
