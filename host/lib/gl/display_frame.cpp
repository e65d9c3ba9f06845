#include "display_frame.hpp"

#include "image_texture.hpp"

namespace pfx::gl {
namespace {

// RGBA8, SRGB8_ALPHA8 or an unsized RGBA of bytes: a blit moves its bits as they are.
bool is_eight_bit(GLuint texture) {
  GLint red = 0, alpha = 0, type = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_RED_SIZE, &red);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_ALPHA_SIZE, &alpha);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_RED_TYPE, &type);
  return red == 8 && alpha == 8 && type == GL_UNSIGNED_NORMALIZED;
}

// Red read as blue and blue as red (texture(), texelFetch(); not blits, which move bits).
void swap_red_blue(GLuint texture, bool swap) {
  glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_R, swap ? GL_BLUE : GL_RED);
  glTextureParameteri(texture, GL_TEXTURE_SWIZZLE_B, swap ? GL_RED : GL_BLUE);
}

}  // namespace

using app::create_texture;

bool DisplayFrame::create(std::string* error) {
  if (!transfer_programs_.create(error)) return false;
  glCreateFramebuffers(1, &read_framebuffer_);
  glCreateFramebuffers(1, &draw_framebuffer_);
  return true;
}

DisplayFrame::~DisplayFrame() {
  delete_textures();
  if (read_framebuffer_) glDeleteFramebuffers(1, &read_framebuffer_);
  if (draw_framebuffer_) glDeleteFramebuffers(1, &draw_framebuffer_);
}

void DisplayFrame::delete_textures() {
  in_.release();
  out_.release();
  for (GLuint* texture : {&wide_color_, &wide_output_}) {
    if (*texture) glDeleteTextures(1, texture);
    *texture = 0;
  }
}

void DisplayFrame::resize(int width, int height) {
  if (width == width_ && height == height_ && in_.texture) return;
  delete_textures();
  width_ = width;
  height_ = height;
  in_.create(width, height);
  out_.create(width, height);
}

GLuint DisplayFrame::color() const { return wide_frame_ ? wide_color_ : in_.as(transfer_); }
GLuint DisplayFrame::output() const { return wide_frame_ ? wide_output_ : out_.as(transfer_); }

GLuint DisplayFrame::eight_bit_behind(GLuint texture) const {
  for (const EightBitTexture* bytes : {&in_, &out_})
    if (bytes->holds(texture)) return bytes->texture;
  return 0;
}

void DisplayFrame::decode_bytes(const uint8_t* rgba, app::Transfer transfer) {
  transfer_ = transfer;
  wide_frame_ = false;
  // The rest of the unpack state is the context's default in every host that calls this with
  // bytes (a context of its own).
  in_.upload_top_first(rgba, width_, height_);
}

void DisplayFrame::decode_bytes_exact(const uint8_t* rgba, app::Transfer transfer) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(in_.texture, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  decode_pass(in_.texture, transfer);
}

void DisplayFrame::decode_texture(GLuint frame_texture, app::Transfer transfer, bool bgra) {
  if (is_eight_bit(frame_texture)) {
    transfer_ = transfer;
    wide_frame_ = false;
    // The bits as they are; the chain reads them through a texture that swaps red and blue back
    // (the swizzle applies to sampling, so the swap costs nothing).
    blit_flipped(frame_texture, in_.texture);
    swap_red_blue(in_.as(transfer), bgra);
  } else {
    swap_red_blue(frame_texture, bgra);
    decode_pass(frame_texture, transfer);
    swap_red_blue(frame_texture, false);
  }
}

void DisplayFrame::decode_pass(GLuint source, app::Transfer transfer) {
  transfer_ = transfer;
  wide_frame_ = true;
  if (!wide_color_) wide_color_ = create_texture(GL_RGBA16F, width_, height_);
  if (!wide_output_) wide_output_ = create_texture(GL_RGBA16F, width_, height_);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, wide_color_, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_framebuffer_);
  glViewport(0, 0, width_, height_);
  transfer_programs_.decode(source, transfer, height_);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

void DisplayFrame::blit_flipped(GLuint from, GLuint to) {
  // The bits as they are, whatever either texture's encoding: no sRGB conversion in the blit.
  glDisable(GL_FRAMEBUFFER_SRGB);
  glNamedFramebufferTexture(read_framebuffer_, GL_COLOR_ATTACHMENT0, from, 0);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, to, 0);
  glBlitNamedFramebuffer(read_framebuffer_, draw_framebuffer_, 0, 0, width_, height_, 0, height_, width_, 0,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // Not kept attached: the host's texture may be deleted before the next frame.
  glNamedFramebufferTexture(read_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

void DisplayFrame::swap_copy_flipped(GLuint from, GLuint to) {
  glDisable(GL_FRAMEBUFFER_SRGB);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, to, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_framebuffer_);
  glViewport(0, 0, width_, height_);
  swap_red_blue(from, true);
  // The linear "decode" is the identity: each code lands on itself.
  transfer_programs_.decode(from, app::Transfer::LINEAR, height_);
  swap_red_blue(from, false);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

void DisplayFrame::encode_pass(GLuint result, GLuint frame_texture, app::Transfer transfer) {
  glDisable(GL_FRAMEBUFFER_SRGB);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, frame_texture, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_framebuffer_);
  glViewport(0, 0, width_, height_);
  transfer_programs_.encode(result, transfer, height_);
  glNamedFramebufferTexture(draw_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

void DisplayFrame::encode_texture(GLuint result, GLuint frame_texture, app::Transfer transfer, bool bgra) {
  const GLuint bytes = eight_bit_behind(result);
  if (bytes && is_eight_bit(frame_texture)) {
    // The frame's own bits go back as they came; what the chain drew holds red first, and a blit
    // cannot swap it.
    if (bgra && bytes == out_.texture) swap_copy_flipped(bytes, frame_texture);
    else blit_flipped(bytes, frame_texture);
    return;
  }
  // The encode writes R, G, B, A through a framebuffer, where no swizzle applies: the result's
  // channels are swapped as it is read instead.
  swap_red_blue(result, bgra);
  encode_pass(result, frame_texture, transfer);
  swap_red_blue(result, false);
}

void DisplayFrame::encode_bytes(GLuint result, app::Transfer transfer, uint8_t* rgba) {
  const GLuint bytes = eight_bit_behind(result);
  if (!bytes) {
    // A linear result (RGBA16F): encoded by the pass, which also flips.
    encode_pass(result, out_.texture, transfer);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(out_.texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, width_ * height_ * 4, rgba);
    return;
  }
  (in_.texture == bytes ? in_ : out_).read_top_first(rgba, width_, height_);
}

}  // namespace pfx::gl
