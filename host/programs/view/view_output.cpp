#include "view_output.hpp"

#include <vector>

#include "display_transfer.hpp"
#include "image_texture.hpp"

namespace pfx::app {

ViewOutput::~ViewOutput() { release(); }

void ViewOutput::release() {
  for (int i = 0; i < 2; ++i) {
    delete_texture(linear_[i]);
    linear_[i] = 0;
    eight_bit_[i].release();
  }
}

void ViewOutput::resize(int width, int height, bool codes) {
  if (width == width_ && height == height_ && codes == codes_ && shown()) return;
  release();
  for (int i = 0; i < 2; ++i) {
    if (codes)
      eight_bit_[i].create(width, height);
    else
      linear_[i] = create_color_texture(width, height);
  }
  width_ = width;
  height_ = height;
  codes_ = codes;
  front_ = 0;
}

uint32_t ViewOutput::target() const {
  const int back = 1 - front_;
  return codes_ ? eight_bit_[back].srgb_view : linear_[back];
}

void ViewOutput::swap() { front_ = 1 - front_; }

uint32_t ViewOutput::shown() const { return codes_ ? eight_bit_[front_].texture : linear_[front_]; }

DisplayImage ViewOutput::encoded(int channels) const {
  DisplayImage image;
  image.width = width_;
  image.height = height_;
  image.channels = 4;
  image.pixels.resize(size_t(width_) * height_ * 4);
  eight_bit_[front_].read_top_first(image.pixels.data(), width_, height_);
  if (channels == 3) image.drop_alpha();
  return image;
}

Image ViewOutput::linear() const {
  if (!codes_) return download_color_texture(linear_[front_], width_, height_);
  return decode_display_image(encoded(4), Transfer::SRGB);
}

}  // namespace pfx::app
