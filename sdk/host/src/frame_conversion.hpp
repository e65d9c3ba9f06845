// A host of display frames may hand the chain its colour and output as 8-bit textures (GL_RGBA8
// holding linear values, GL_SRGB8_ALPHA8 holding sRGB-encoded ones: chain.hpp's FrameTextures).
// An effect that promised PFX_DECLARATION_SAMPLES_AND_DRAWS samples and draws them as they are;
// for one that did not, the chain keeps the ABI's RGBA16F promise with a copy of its own on that
// side, made and read back by drawing (so sampling decodes sRGB and drawing encodes it, as the
// promised path does). This owns those copies and the program that moves pixels between textures.
#pragma once

#include <cstdint>
#include <string>

#include <glad/gl.h>

namespace pfx::host {

// Whether a texture the host handed in is one of the 8-bit kinds above (asked of GL each frame:
// cheap, and a host may swap textures between frames).
bool is_eight_bit_texture(GLuint texture);
// Whether sampling `texture` gives its channels as they are stored (no swizzle set): only then may
// its bits be copied instead of drawn.
bool samples_as_stored(GLuint texture);
// Whether drawing into `framebuffer` (0: the default one) with GL_FRAMEBUFFER_SRGB on encodes: its
// first draw buffer is sRGB-capable.
bool framebuffer_draws_srgb(GLuint framebuffer);

class FrameConversion {
 public:
  FrameConversion() = default;
  ~FrameConversion();
  FrameConversion(const FrameConversion&) = delete;
  FrameConversion& operator=(const FrameConversion&) = delete;

  // The RGBA16F copy of the frame's colour (an 8-bit colour drawn into it) and the RGBA16F texture
  // the last effect writes instead of an 8-bit output, at the frame's size; made on first use and
  // kept while the size holds. False with *error when the copy program does not compile.
  bool widen_color(GLuint color, uint32_t width, uint32_t height, GLuint* wide, std::string* error);
  GLuint wide_output(uint32_t width, uint32_t height);
  // Draws `from` into `to` pixel for pixel (both of the frame's size), with GL_FRAMEBUFFER_SRGB on
  // so that an sRGB `to` is encoded; leaves the pass state of docs/sdk.md §1.5 as it found it,
  // but for the draw framebuffer, which the next pass binds anyway.
  bool draw_copy(GLuint from, GLuint to, uint32_t width, uint32_t height, std::string* error);
  // The same into a framebuffer of the host's (its selected draw buffer), encoding when `srgb`.
  bool draw_into(GLuint from, GLuint framebuffer, bool srgb, uint32_t width, uint32_t height, std::string* error);
  // Bytes of the copies alive now, for the frame's peak target memory.
  uint64_t bytes() const;

 private:
  struct Texture {
    GLuint texture = 0, framebuffer = 0;
    uint32_t width = 0, height = 0;
  };
  static void fit(Texture* texture, uint32_t width, uint32_t height);
  static void release(Texture* texture);
  bool make_program(std::string* error);
  Texture color_, output_;
  GLuint program_ = 0, target_framebuffer_ = 0, vertex_array_ = 0;
};

}  // namespace pfx::host
