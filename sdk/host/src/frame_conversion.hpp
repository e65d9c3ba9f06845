// A host of display frames may hand the chain its colour and output as 8-bit textures (GL_RGBA8
// holding linear values, GL_SRGB8_ALPHA8 holding sRGB-encoded ones: chain.hpp's FrameTextures).
// An effect that promised PFX_DECLARATION_SAMPLES_AND_DRAWS samples and draws them as they are;
// for one that did not, the chain keeps the ABI's RGBA16F promise with a copy of its own on that
// side, made and read back by drawing (so sampling decodes sRGB and drawing encodes it, as the
// promised path does). A display-referred effect (PFX_DECLARATION_DISPLAY_REFERRED) wants sRGB
// codes instead: where the host's frame is not 8-bit sRGB the chain encodes into a copy of codes
// and decodes out of one, and the same programs convert between two effects that disagree. This
// owns those copies and the programs that move pixels between textures.
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

// What a conversion draw does to each texel: nothing, linear light to sRGB codes (clamped to
// [0, 1], NaN to 0), or sRGB codes to linear light; alpha passes through.
enum class Transfer { COPY, ENCODE, DECODE };

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
  // The same as RGBA8 textures of sRGB codes, for a display-referred effect at either end of the
  // chain whose host frame cannot be handed to it as codes directly.
  GLuint codes_color(uint32_t width, uint32_t height);
  GLuint codes_output(uint32_t width, uint32_t height);
  // Draws `from` into `to` pixel for pixel (both of the frame's size), with GL_FRAMEBUFFER_SRGB on
  // so that an sRGB `to` is encoded (off for ENCODE, which writes codes itself); leaves the pass
  // state of docs/sdk.md §1.5 as it found it, but for the draw framebuffer, which the next pass
  // binds anyway.
  bool draw_copy(GLuint from, GLuint to, uint32_t width, uint32_t height, std::string* error,
                 Transfer transfer = Transfer::COPY);
  // The same into a framebuffer (its selected draw buffer), encoding when `srgb`.
  bool draw_into(GLuint from, GLuint framebuffer, bool srgb, uint32_t width, uint32_t height, std::string* error,
                 Transfer transfer = Transfer::COPY);
  // Bytes of the copies alive now, for the frame's peak target memory.
  uint64_t bytes() const;

 private:
  struct Texture {
    GLuint texture = 0, framebuffer = 0;
    uint32_t width = 0, height = 0;
    uint64_t bytes_per_texel = 0;
  };
  static void fit(Texture* texture, GLenum format, uint32_t width, uint32_t height);
  static void release(Texture* texture);
  // The program for `transfer`, compiled on first use; 0 with *error.
  GLuint program(Transfer transfer, std::string* error);
  Texture color_, output_, codes_color_, codes_output_;
  GLuint programs_[3] = {0, 0, 0};
  GLuint target_framebuffer_ = 0, vertex_array_ = 0;
};

}  // namespace pfx::host
