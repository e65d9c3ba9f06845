// Moving the application's frame into the chain and the chain's result back: the back buffer's
// colour (and depth, when the default framebuffer has one) blitted into textures, the colour kept
// 8-bit and handed to the chain as libpfxhost takes a display frame (an sRGB view that decodes as
// it is sampled, or the plain bytes for linear codes). The chain draws its result straight into
// the back buffer where the back buffer can take it (sRGB codes need an sRGB-capable one, which
// encodes as it is drawn into); elsewhere into an 8-bit texture blitted back. No pass converts the
// frame unless an effect at an end of the chain did not promise to only sample and draw it (the
// chain converts then). Runs inside a GlStateGuard; touches only its own objects,
// GL_FRAMEBUFFER_SRGB (off for the blits) and the default framebuffer's read and draw buffer,
// which it puts back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "eight_bit_texture.hpp"
#include "image.hpp"
#include "inject_settings.hpp"

namespace pfx::inject {

class FrameCopy {
 public:
  // Makes the framebuffers it reads and draws through; the context must be current.
  void create();
  ~FrameCopy();  // the context must be current

  // Matches the textures to the back buffer: its size, and whether and how it stores depth.
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  bool has_depth() const { return depth_ != 0; }
  // True once after a depth copy failed and depth was dropped (depth_description() says why).
  bool take_depth_lost() {
    const bool lost = depth_lost_;
    depth_lost_ = false;
    return lost;
  }
  // What the default framebuffer's depth is, or why there is none, for the log.
  const std::string& depth_description() const { return depth_description_; }

  // Copies the back buffer's depth into depth(), when it has depth. A refused copy only drops
  // depth (has_depth() turns false). Apart from the colour: depth decides whether the chain runs
  // passes at all, and the colour is copied only when it does.
  void copy_depth_in();
  // Copies the back buffer into color(), which reads it as `transfer` says. False with *error
  // when GL refused.
  bool copy_colour_in(Transfer transfer, std::string* error);
  // Copies `texture` (color() or output()) into the back buffer.
  void copy_out(GLuint texture);
  // Whether the chain can draw its result straight into the back buffer, for the transfer given to
  // copy_colour_in: the codes are linear, or the back buffer is sRGB-capable.
  bool back_buffer_takes_output() const;
  // Runs `draw` with the back buffer as the default framebuffer's draw buffer, then puts back the
  // application's; what `draw` returns.
  template <typename Draw>
  bool into_back_buffer(Draw draw) {
    GLint draw_buffer = GL_BACK;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
    glDrawBuffer(GL_BACK);
    const bool drawn = draw();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDrawBuffer(static_cast<GLenum>(draw_buffer));
    return drawn;
  }

  // 8-bit textures of the frame's size, as the chain reads and writes them for the transfer given
  // to copy_colour_in: sRGB views, or the plain RGBA8 textures for linear codes.
  GLuint color() const { return colour_in_.as(transfer_); }
  GLuint output() const { return colour_out_.as(transfer_); }
  GLuint depth() const { return depth_; }
  // color() or output() in linear light, row 0 at the top (decoded with the exact curve), for
  // captures.
  app::Image linear_image(GLuint texture) const;
  // The back buffer in linear light, as linear_image() gives a texture: for captures of a result
  // the chain drew there.
  app::Image linear_back_buffer() const;
  // The back buffer as it will be presented, row 0 at the top.
  app::DisplayImage read_back_buffer() const;

 private:
  void delete_targets();
  void choose_depth_format();
  // The back buffer's RGBA8 codes, row 0 at the top.
  std::vector<std::uint8_t> back_buffer_top_first() const;
  gl::EightBitTexture colour_in_;   // the back buffer's bytes as they are
  gl::EightBitTexture colour_out_;  // the chain's result, as it will be presented
  Transfer transfer_ = Transfer::SRGB;
  GLuint depth_ = 0;              // the default framebuffer's depth format, or 0
  GLuint read_framebuffer_ = 0, out_framebuffer_ = 0;
  GLenum depth_format_ = 0;
  bool back_buffer_srgb_ = false;  // the back buffer encodes sRGB as GL_FRAMEBUFFER_SRGB draws into it
  bool depth_lost_ = false;
  std::string depth_description_;
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::inject
