// An 8-bit display-referred frame (a video frame, a PNG) on its way through the chain, so every
// host of such frames (pfx-render with an 8-bit --input, the frei0r plugins, the GStreamer element,
// the OBS filter, Python, the Vulkan bridge) gives the same bytes for the same frame.
//
// The frame stays 8-bit: its bytes (or the host's texture, by a blit) land in an RGBA8 texture,
// and the chain reads it as it is, through an sRGB view for the sRGB transfer (sampling decodes
// it: libpfxhost's FrameTextures); the chain's result is drawn into another such texture (drawing
// encodes) and handed back the same way. No pass of pfx's own converts the frame unless an effect
// at either end of the chain did not promise to only sample and draw it, and then the chain does
// that one conversion (pfx/effect.h, PFX_DECLARATION_SAMPLES_AND_DRAWS). A host texture of
// another format (RGB10_A2 from a 10-bit swapchain) is decoded into RGBA16F and encoded back by
// transfer_programs, which keeps its two extra bits.
//
// Frames arrive top row first (video, image files, GStreamer's GL textures); the chain works on
// GL's bottom-row-first textures, so the way in and the way out flip the rows: bytes row by row
// as they are uploaded and read back, textures within the blit (or the draw, for a texture whose
// red and blue trade places). Every call with the context
// current; the calls bind framebuffers, the viewport, a program, a vertex array and texture unit
// 0, disable GL_FRAMEBUFFER_SRGB and leave all that so (a host inside somebody else's context
// wraps them in a GlStateGuard).
#pragma once

#include <cstdint>
#include <string>

#include <glad/gl.h>

#include "display_transfer.hpp"
#include "eight_bit_texture.hpp"
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
  // The same, decoded by transfer_programs with the exact curve into RGBA16F, for a host that wants
  // the result in linear light at full precision (pfx-render writing an EXR): the GPU's own sRGB
  // decode is exact on GPUs, but Mesa's llvmpipe approximates it (up to 2.5 % off at the darkest
  // codes). Then color() and output() are RGBA16F; encode_bytes(output()) encodes exactly too.
  void decode_bytes_exact(const uint8_t* rgba, app::Transfer transfer);
  // A texture of the frame's size holding unsigned normalised RGBA (RGBA8, SRGB8_ALPHA8, RGB10_A2),
  // row 0 at the top, into color(). `bgra`: its texels hold blue where red belongs and red where
  // blue does (a Vulkan B8G8R8A8 or A2R10G10B10 image in memory GL reads as RGBA): the way in and
  // out swaps them, so the chain sees and writes red as red.
  void decode_texture(GLuint frame_texture, app::Transfer transfer, bool bgra = false);
  // The chain's result (output(), color(), or any texture of the frame's size holding linear light
  // to sample) encoded to 8 bits, read back into `rgba` (row 0 at the top).
  void encode_bytes(GLuint result, app::Transfer transfer, uint8_t* rgba);
  // The result encoded into `frame_texture` (RGBA8, SRGB8_ALPHA8 or RGB10_A2, the frame's size, row 0
  // at the top; `bgra` as for decode_texture).
  void encode_texture(GLuint result, GLuint frame_texture, app::Transfer transfer, bool bgra = false);

  // What the chain reads and the texture it writes, both of the frame's size: after an 8-bit frame
  // 8-bit textures as the transfer reads them (an sRGB view, or plain RGBA8 holding linear
  // values), after a wider one or decode_bytes_exact RGBA16F.
  GLuint color() const;
  GLuint output() const;

 private:
  void delete_textures();
  // The RGBA8 texture behind `texture` when it is one of this frame's 8-bit textures, else 0.
  GLuint eight_bit_behind(GLuint texture) const;
  void blit_flipped(GLuint from, GLuint to);
  // The bits of one 8-bit texture into another, rows flipped, red and blue trading places: a blit
  // cannot swap channels, so a draw (unsigned normalised to unsigned normalised: exact). Only the
  // way out needs it: the way in blits, and the chain samples through a swizzle.
  void swap_copy_flipped(GLuint from, GLuint to);
  void encode_pass(GLuint result, GLuint frame_texture, app::Transfer transfer);
  // Decodes `source` (top row first) by transfer_programs into the RGBA16F colour.
  void decode_pass(GLuint source, app::Transfer transfer);

  TransferPrograms transfer_programs_;
  EightBitTexture in_, out_;                   // the frame as it came, and as it goes out
  GLuint wide_color_ = 0, wide_output_ = 0;    // RGBA16F, made when a frame or host needs them
  GLuint read_framebuffer_ = 0, draw_framebuffer_ = 0;
  app::Transfer transfer_ = app::Transfer::SRGB;
  bool wide_frame_ = false;                    // the last frame is RGBA16F in the chain: wider or exact
  int width_ = 0, height_ = 0;
};

}  // namespace pfx::gl
