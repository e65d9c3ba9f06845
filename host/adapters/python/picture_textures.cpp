#include "picture_textures.hpp"

#include <glad/gl.h>

#include "image_texture.hpp"

namespace pfx::python {

void PictureTextures::upload(const app::Image& picture) {
  const bool has_colour = !picture.rgba.empty();
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
  if (color_) app::fill_color_texture(color_, picture);
  if (depth_) app::fill_depth_texture(depth_, picture);
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
}

}  // namespace pfx::python
