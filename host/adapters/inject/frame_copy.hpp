// Moving the application's frame into the chain and the chain's result back: the back buffer's
// colour (and depth, when the default framebuffer has one) copied into textures, the 8-bit values
// decoded to linear light in RGBA16F for the chain's `color`, and the chain's output encoded back
// into the back buffer. Runs inside a GlStateGuard; touches only its own objects and the default
// framebuffer's read and draw buffer, which it puts back.
#pragma once

#include <string>

#include <glad/gl.h>

#include "image.hpp"
#include "inject_settings.hpp"
#include "transfer_programs.hpp"

namespace pfx::inject {

class FrameCopy {
 public:
  // Compiles the two programs; false with *error (the context lacks what they need).
  bool create(std::string* error);
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
  // Copies the back buffer into color(), decoded as `transfer` says. False with *error when GL
  // refused.
  bool copy_colour_in(Transfer transfer, std::string* error);
  // Encodes `texture` (RGBA16F, the frame's size) into the back buffer.
  void copy_out(GLuint texture, Transfer transfer);

  GLuint color() const { return color_; }
  GLuint depth() const { return depth_; }
  GLuint output() const { return output_; }
  // The back buffer as it will be presented, row 0 at the top.
  app::DisplayImage read_back_buffer() const;
  // Median time of one full-frame RGBA16F copy pass (glFinish and a clock), the unit the
  // overhead is quoted in.
  double copy_pass_ms(int repeats);

 private:
  void delete_targets();
  void choose_depth_format();
  gl::TransferPrograms transfer_;
  GLuint copy_program_ = 0, vertex_array_ = 0;
  GLuint back_buffer_copy_ = 0;   // RGBA8: the back buffer's bytes as they are
  GLuint color_ = 0, output_ = 0; // RGBA16F
  GLuint depth_ = 0;              // the default framebuffer's depth format, or 0
  GLuint read_framebuffer_ = 0, decode_framebuffer_ = 0, scratch_framebuffer_ = 0;
  GLenum depth_format_ = 0;
  bool depth_lost_ = false;
  std::string depth_description_;
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::inject
