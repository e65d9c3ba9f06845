#include "eight_bit_texture.hpp"

#include <algorithm>
#include <cstddef>

#include "image_texture.hpp"

namespace pfx::gl {

void EightBitTexture::create(int width, int height) {
  release();
  // Immutable storage, so that a view of it can exist.
  texture = app::create_texture(GL_RGBA8, width, height);
  glGenTextures(1, &srgb_view);
  glTextureView(srgb_view, GL_TEXTURE_2D, texture, GL_SRGB8_ALPHA8, 0, 1, 0, 1);
}

void EightBitTexture::release() {
  if (srgb_view) glDeleteTextures(1, &srgb_view);
  if (texture) glDeleteTextures(1, &texture);
  texture = srgb_view = 0;
}

void EightBitTexture::upload_top_first(const uint8_t* rgba, int width, int height) const {
  // Row by row into GL's order: the turn costs nothing beyond the upload itself. Rows of 4-byte
  // pixels are always 4-byte aligned.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const size_t row = size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    glTextureSubImage2D(texture, 0, 0, height - 1 - y, width, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba + row * y);
}

void EightBitTexture::read_top_first(uint8_t* rgba, int width, int height) const {
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  const size_t row = size_t(width) * 4;
  glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(row * height), rgba);
  // GL's bottom row first to the top row first, in place.
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(rgba + row * y, rgba + row * (y + 1), rgba + row * (height - 1 - y));
}

}  // namespace pfx::gl
