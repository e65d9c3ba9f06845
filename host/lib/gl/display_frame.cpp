#include "display_frame.hpp"

#include "image_texture.hpp"

namespace pfx::gl {

using app::create_texture;

bool DisplayFrame::create(std::string* error) {
  if (!transfer_.create(error)) return false;
  glCreateFramebuffers(1, &decode_framebuffer_);
  glCreateFramebuffers(1, &encode_framebuffer_);
  return true;
}

DisplayFrame::~DisplayFrame() {
  delete_textures();
  if (decode_framebuffer_) glDeleteFramebuffers(1, &decode_framebuffer_);
  if (encode_framebuffer_) glDeleteFramebuffers(1, &encode_framebuffer_);
}

void DisplayFrame::delete_textures() {
  const GLuint textures[] = {staging_, color_, output_};
  if (staging_) glDeleteTextures(3, textures);
  staging_ = color_ = output_ = 0;
}

void DisplayFrame::resize(int width, int height) {
  if (width == width_ && height == height_ && staging_) return;
  delete_textures();
  width_ = width;
  height_ = height;
  staging_ = create_texture(GL_RGBA8, width, height);
  color_ = create_texture(GL_RGBA16F, width, height);
  output_ = create_texture(GL_RGBA16F, width, height);
  glNamedFramebufferTexture(decode_framebuffer_, GL_COLOR_ATTACHMENT0, color_, 0);
}

void DisplayFrame::decode_bytes(const uint8_t* rgba, app::Transfer transfer) {
  // Rows of 4-byte pixels are always 4-byte aligned; the rest of the unpack state is the
  // context's default in every host that calls this with bytes (a context of its own).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(staging_, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  decode_texture(staging_, transfer);
}

void DisplayFrame::decode_texture(GLuint frame_texture, app::Transfer transfer) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, decode_framebuffer_);
  glViewport(0, 0, width_, height_);
  transfer_.decode(frame_texture, transfer, height_);
}

void DisplayFrame::encode_texture(GLuint linear, GLuint frame_texture, app::Transfer transfer) {
  glNamedFramebufferTexture(encode_framebuffer_, GL_COLOR_ATTACHMENT0, frame_texture, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, encode_framebuffer_);
  glViewport(0, 0, width_, height_);
  transfer_.encode(linear, transfer, height_);
  // Not kept attached: the texture is somebody else's and may be deleted before the next frame.
  glNamedFramebufferTexture(encode_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

void DisplayFrame::encode_bytes(GLuint linear, app::Transfer transfer, uint8_t* rgba) {
  encode_texture(linear, staging_, transfer);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(staging_, 0, GL_RGBA, GL_UNSIGNED_BYTE, width_ * height_ * 4, rgba);
}

}  // namespace pfx::gl
