// An 8-bit display frame on the GPU as libpfxhost's chain takes one (chain.hpp, FrameTextures): an
// immutable RGBA8 texture, and an sRGB view of the same bits, which decodes to linear light as it
// is sampled and encodes as it is drawn into (with GL_FRAMEBUFFER_SRGB). Frames arrive top row
// first (video, image files, a window read back); GL keeps the bottom row first, so the rows are
// turned over on their way in and out, as part of the upload and the read back. The context must
// be current for every call and for release().
#pragma once

#include <cstdint>

#include <glad/gl.h>

#include "display_transfer.hpp"

namespace pfx::gl {

struct EightBitTexture {
  GLuint texture = 0, srgb_view = 0;

  // Makes both at the size (releasing what was there).
  void create(int width, int height);
  void release();
  // What the chain reads or draws for the transfer: the sRGB view, or the plain texture for codes
  // that are linear light.
  GLuint as(app::Transfer transfer) const { return transfer == app::Transfer::SRGB ? srgb_view : texture; }
  // Whether `name` is one of the two.
  bool holds(GLuint name) const { return name && (name == texture || name == srgb_view); }
  // Tightly packed RGBA bytes, row 0 at the top, in and out.
  void upload_top_first(const uint8_t* rgba, int width, int height) const;
  void read_top_first(uint8_t* rgba, int width, int height) const;
};

}  // namespace pfx::gl
