#include "frame_copy.hpp"

#include <algorithm>
#include <vector>


#include "display_transfer.hpp"

namespace pfx::inject {
namespace {

GLuint make_texture(GLenum format, int width, int height) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

void FrameCopy::create() {
  glCreateFramebuffers(1, &read_framebuffer_);
  glCreateFramebuffers(1, &out_framebuffer_);
}

FrameCopy::~FrameCopy() {
  delete_targets();
  const GLuint framebuffers[] = {read_framebuffer_, out_framebuffer_};
  glDeleteFramebuffers(2, framebuffers);
}

void FrameCopy::delete_targets() {
  colour_in_.release();
  colour_out_.release();
  glDeleteTextures(1, &depth_);
  depth_ = 0;
}

// A depth blit needs the same format on both sides, so the copy takes the default framebuffer's.
void FrameCopy::choose_depth_format() {
  depth_format_ = 0;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  GLint type = GL_NONE, bits = 0, stencil_bits = 0, component = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_NONE) {
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                          &component);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                          &stencil_bits);
  }
  if (bits == 0) {
    depth_description_ = "the default framebuffer has no depth buffer";
    return;
  }
  if (component == GL_FLOAT) depth_format_ = stencil_bits ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
  else if (bits == 24) depth_format_ = stencil_bits ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
  else if (bits == 16) depth_format_ = GL_DEPTH_COMPONENT16;
  else if (bits == 32) depth_format_ = GL_DEPTH_COMPONENT32;
  depth_description_ = std::to_string(bits) + "-bit " + (component == GL_FLOAT ? "float " : component == GL_UNSIGNED_NORMALIZED ? "unorm " : "type " + std::to_string(component) + " ") + "depth" +
                       (stencil_bits ? " with " + std::to_string(stencil_bits) + "-bit stencil" : "");
  if (!depth_format_) depth_description_ += ", a format the copy does not know";
}

void FrameCopy::resize(int width, int height) {
  if (width == width_ && height == height_ && colour_in_.texture) return;
  delete_targets();
  width_ = width;
  height_ = height;
  colour_in_.create(width, height);
  colour_out_.create(width, height);
  choose_depth_format();
  GLint encoding = GL_LINEAR;
  glGetNamedFramebufferAttachmentParameteriv(0, GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
  back_buffer_srgb_ = encoding == GL_SRGB;
  if (depth_format_) depth_ = make_texture(depth_format_, width, height);
  glNamedFramebufferTexture(read_framebuffer_, GL_COLOR_ATTACHMENT0, colour_in_.texture, 0);
  const bool stencil = depth_format_ == GL_DEPTH24_STENCIL8 || depth_format_ == GL_DEPTH32F_STENCIL8;
  glNamedFramebufferTexture(read_framebuffer_, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth_, 0);
}

void FrameCopy::copy_depth_in() {
  if (!depth_) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, read_framebuffer_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const GLenum depth_error = glGetError();
  if (depth_error == GL_NO_ERROR) return;
  depth_description_ += ", which the GL would not copy (error " + std::to_string(depth_error) +
                        "): the chain runs without depth";
  depth_lost_ = true;
  glNamedFramebufferTexture(read_framebuffer_, GL_DEPTH_ATTACHMENT, 0, 0);
  glNamedFramebufferTexture(read_framebuffer_, GL_DEPTH_STENCIL_ATTACHMENT, 0, 0);
  glDeleteTextures(1, &depth_);
  depth_ = 0;
}

bool FrameCopy::copy_colour_in(Transfer transfer, std::string* error) {
  while (glGetError() != GL_NO_ERROR) {
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  GLint read_buffer = GL_BACK;
  glGetIntegerv(GL_READ_BUFFER, &read_buffer);
  glReadBuffer(GL_BACK);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, read_framebuffer_);
  // The bits as they are: an sRGB-capable back buffer is neither decoded nor encoded.
  glDisable(GL_FRAMEBUFFER_SRGB);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const GLenum colour_error = glGetError();
  glReadBuffer(static_cast<GLenum>(read_buffer));
  if (colour_error != GL_NO_ERROR) {
    *error = "copying the back buffer failed (GL error " + std::to_string(colour_error) + ")";
    return false;
  }
  transfer_ = transfer;
  return true;
}

void FrameCopy::copy_out(GLuint texture) {
  const GLuint bytes = colour_out_.holds(texture) ? colour_out_.texture : colour_in_.texture;
  glNamedFramebufferTexture(out_framebuffer_, GL_COLOR_ATTACHMENT0, bytes, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, out_framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  GLint draw_buffer = GL_BACK;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  glDrawBuffer(GL_BACK);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDrawBuffer(static_cast<GLenum>(draw_buffer));
}

bool FrameCopy::back_buffer_takes_output() const { return transfer_ == Transfer::LINEAR || back_buffer_srgb_; }

app::Image FrameCopy::linear_image(GLuint texture) const {
  app::DisplayImage image;
  image.width = width_;
  image.height = height_;
  image.channels = 4;
  image.pixels.resize(static_cast<size_t>(width_) * height_ * 4);
  (colour_out_.holds(texture) ? colour_out_ : colour_in_).read_top_first(image.pixels.data(), width_, height_);
  return app::decode_display_image(image, transfer_);
}

std::vector<std::uint8_t> FrameCopy::back_buffer_top_first() const {
  const size_t row = static_cast<size_t>(width_) * 4;
  std::vector<std::uint8_t> bottom_first(row * height_), top_first(row * height_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  GLint read_buffer = GL_BACK;
  glGetIntegerv(GL_READ_BUFFER, &read_buffer);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_first.data());
  glReadBuffer(static_cast<GLenum>(read_buffer));
  // GL's rows start at the bottom; an image's at the top.
  for (int y = 0; y < height_; ++y)
    std::copy_n(bottom_first.data() + (height_ - 1 - y) * row, row, top_first.data() + y * row);
  return top_first;
}

app::Image FrameCopy::linear_back_buffer() const {
  app::DisplayImage image;
  image.width = width_;
  image.height = height_;
  image.channels = 4;
  image.pixels = back_buffer_top_first();
  return app::decode_display_image(image, transfer_);
}

app::DisplayImage FrameCopy::read_back_buffer() const {
  app::DisplayImage image;
  image.width = width_;
  image.height = height_;
  image.channels = 3;
  const std::vector<std::uint8_t> rgba = back_buffer_top_first();
  // A window's alpha is not part of what is seen, so the picture keeps RGB.
  image.pixels.resize(static_cast<size_t>(width_) * height_ * 3);
  for (size_t i = 0; i < static_cast<size_t>(width_) * height_; ++i)
    for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = rgba[i * 4 + c];
  return image;
}

}  // namespace pfx::inject
