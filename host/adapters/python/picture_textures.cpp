#include "picture_textures.hpp"

#include <cstring>

#include <glad/gl.h>

#include "image_texture.hpp"

namespace pfx::python {

namespace {

// Between the caller's rows (top first, `channels` floats a pixel) and GL's (bottom first, RGBA):
// one pass, alpha opaque on the way in where the caller has none.
void rows_to_gl(const float* in, int width, int height, int channels, float* out) {
  const size_t row = static_cast<size_t>(width);
  for (int y = 0; y < height; ++y) {
    const float* from = in + static_cast<size_t>(height - 1 - y) * row * channels;
    float* to = out + static_cast<size_t>(y) * row * 4;
    if (channels == 4) {
      std::memcpy(to, from, row * 4 * sizeof(float));
      continue;
    }
    for (size_t x = 0; x < row; ++x) {
      std::memcpy(to + x * 4, from + x * 3, 3 * sizeof(float));
      to[x * 4 + 3] = 1.0f;
    }
  }
}

void rows_from_gl(const float* in, int width, int height, int channels, float* out) {
  const size_t row = static_cast<size_t>(width);
  for (int y = 0; y < height; ++y) {
    const float* from = in + static_cast<size_t>(height - 1 - y) * row * 4;
    float* to = out + static_cast<size_t>(y) * row * channels;
    if (channels == 4) {
      std::memcpy(to, from, row * 4 * sizeof(float));
      continue;
    }
    for (size_t x = 0; x < row; ++x) std::memcpy(to + x * 3, from + x * 4, 3 * sizeof(float));
  }
}

}  // namespace

void PictureTextures::upload(const app::Image& picture, const float* colour, int channels) {
  const bool has_colour = colour != nullptr;
  const bool same = picture.width == width_ && picture.height == height_ && has_colour == (color_ != 0) &&
                    picture.has_depth() == (depth_ != 0);
  if (!same) {
    release();
    width_ = picture.width;
    height_ = picture.height;
    if (has_colour) {
      color_ = app::create_color_texture(width_, height_);
      output_ = app::create_color_texture(width_, height_);
    }
    if (picture.has_depth()) depth_ = app::create_texture(GL_R32F, width_, height_);
  }
  if (color_) {
    staging_.resize(static_cast<size_t>(width_) * height_ * 4);
    rows_to_gl(colour, width_, height_, channels, staging_.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(color_, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, staging_.data());
  }
  if (depth_) app::fill_depth_texture(depth_, picture);
}

void PictureTextures::download(float* out, int channels) {
  staging_.resize(static_cast<size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(output_, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(staging_.size() * sizeof(float)),
                    staging_.data());
  rows_from_gl(staging_.data(), width_, height_, channels, out);
}

host::FrameTextures PictureTextures::inputs() const {
  host::FrameTextures textures;
  textures.color = color_;
  textures.depth = depth_;
  return textures;
}

void PictureTextures::release() {
  app::delete_texture(color_);
  app::delete_texture(depth_);
  app::delete_texture(output_);
  color_ = depth_ = output_ = 0;
  width_ = height_ = 0;
  std::vector<float>().swap(staging_);
}

}  // namespace pfx::python
