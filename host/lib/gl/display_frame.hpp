// An 8-bit display-referred frame (a video frame, a PNG) on its way through the chain: decoded
// into the chain's linear RGBA16F `color`, and the chain's result encoded back to the frame's
// bits, both with transfer_programs, so every host of such frames (pfx-render with an 8-bit
// --input, the frei0r plugins, the GStreamer element) gives the same bytes for the same frame.
//
// Frames arrive top row first (video, image files, GStreamer's GL textures); the chain works on
// GL's bottom-row-first textures, so decode and encode flip the rows. Every call with the
// context current; the calls bind framebuffers, the viewport, a program, a vertex array and
// texture unit 0 and leave them bound (a host inside somebody else's context wraps them in a
// GlStateGuard).
#pragma once

#include <cstdint>
#include <string>

#include <glad/gl.h>

#include "display_transfer.hpp"
#include "transfer_programs.hpp"

namespace pfx::gl {

class DisplayFrame {
 public:
  // Compiles the programs and makes the framebuffers; false with *error.
  bool create(std::string* error);
  ~DisplayFrame();

  // Matches the textures to the frame (a no-op at the same size).
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // Tightly packed RGBA, 8 bits a channel, row 0 at the top, into color().
  void decode_bytes(const uint8_t* rgba, app::Transfer transfer);
  // A texture of the frame's size holding unsigned normalised RGBA (RGBA8, RGB10_A2), row 0 at
  // the top, into color().
  void decode_texture(GLuint frame_texture, app::Transfer transfer);
  // `linear` (RGBA16F, the frame's size) encoded to 8 bits, read back into `rgba` (row 0 at the top).
  void encode_bytes(GLuint linear, app::Transfer transfer, uint8_t* rgba);
  // `linear` encoded into `frame_texture` (RGBA8 or RGB10_A2, the frame's size, row 0 at the top).
  void encode_texture(GLuint linear, GLuint frame_texture, app::Transfer transfer);

  // The decoded frame and a texture of the same kind for the chain's output.
  GLuint color() const { return color_; }
  GLuint output() const { return output_; }

 private:
  void delete_textures();
  TransferPrograms transfer_;
  GLuint staging_ = 0;           // RGBA8: the frame's bytes as they came, and as they go out
  GLuint color_ = 0, output_ = 0;  // RGBA16F
  GLuint decode_framebuffer_ = 0, encode_framebuffer_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::gl
